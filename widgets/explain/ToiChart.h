#pragma once
// The time-of-impact polynomial f(τ) of a collision or pocketing, drawn over its prediction window
// with its real roots marked and the root that gave the event highlighted (Qt Charts).

#include "Explanation.h"

#include <QChartView>

namespace cuelab {

class ToiChart : public QChartView {
    Q_OBJECT
public:
    explicit ToiChart(QWidget* parent = nullptr);
    void setExplanation(const explain::Explanation* e);  // null or no polynomial: an empty chart

    // The drawn window [0, tauMax] (s) and the number of roots marked in it, for tests.
    double tauMax() const { return tauMax_; }
    int markedRoots() const { return marked_; }

private:
    double tauMax_ = 0.0;
    int marked_ = 0;
};

}  // namespace cuelab
