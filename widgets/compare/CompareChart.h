#pragma once
// The position error of every ball over time (Qt Charts), with a cursor at the transport's time.

#include "Divergence.h"

#include <QChartView>

class QLineSeries;
class QValueAxis;

namespace cuelab {

class CompareChart : public QChartView {
    Q_OBJECT
public:
    explicit CompareChart(QWidget* parent = nullptr);

    // One series per ball: |engine - exact| in millimetres against time (s).
    void setComparison(const compare::Comparison& comparison);
    void clear();
    // Moves the cursor line to time t (s).
    void setTime(double t);
    double cursorTime() const { return cursorTime_; }
    QLineSeries* cursor() const { return cursor_; }
    QList<QLineSeries*> ballSeries() const { return balls_; }
    QString errorAxisTitle() const;  // "error (mm)", or "error (m)" once an error passes a metre

private:
    void placeCursor();

    QValueAxis* x_;
    QValueAxis* y_;
    QLineSeries* cursor_;
    QList<QLineSeries*> balls_;
    double cursorTime_ = 0.0;
};

}  // namespace cuelab
