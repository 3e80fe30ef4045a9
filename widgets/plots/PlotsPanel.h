#pragma once
// The Plots dock: speed, slip speed, spin components or kinetic energy (translation, rotation, total)
// against time, for the selected ball or all balls, from the exact closed-form motion (core/plots:
// every point is SimulationResult::stateAt, lines break where a collision makes a value jump).
// Event times are markers on the curves (hover names the event, a click selects it); a cursor line
// follows the transport and is dragged to scrub; the wheel zooms the time axis (Ctrl: the value
// axis), a Shift- or middle-drag pans, a double-click shows everything again.

#include "Curves.h"
#include "Simulation.h"

#include <QWidget>

#include <memory>
#include <vector>

class QComboBox;
class QLabel;
class QToolButton;

namespace cuelab {

class PlotsChartView;

class PlotsPanel : public QWidget {
    Q_OBJECT
public:
    enum class Plot { Speed, SlipSpeed, Spin, Energy, Momentum, EnergyParts, Height };
    Q_ENUM(Plot)

    explicit PlotsPanel(QWidget* parent = nullptr);
    ~PlotsPanel() override;

    void setResult(std::shared_ptr<const SimulationResult> result);
    void setPlot(Plot plot);
    void setAllBalls(bool all);
    Plot plot() const { return plot_; }
    bool allBalls() const { return allBalls_; }

    // What is drawn, for tests and the report: one entry per line on the chart.
    struct Line {
        QString name;  // legend text, e.g. "cue speed"
        std::vector<plots::Polyline> curve;
    };
    const std::vector<Line>& lines() const { return lines_; }
    int markerCount() const;       // event markers drawn
    double cursorTime() const { return time_; }
    PlotsChartView* chartView() const { return view_; }

public slots:
    void setTime(double seconds);      // moves the cursor line (the transport's time)
    void setSelectedBall(int index);   // -1: none (the struck ball is shown)
    void setSelectedEvent(int index);  // highlights the event's marker; -1: none
    void resetZoom();

signals:
    void timeScrubbed(double seconds);  // the user dragged the cursor
    void eventClicked(int index);       // the user clicked an event's marker

private:
    void rebuild();
    int shownBall() const;

    std::shared_ptr<const SimulationResult> result_;
    Plot plot_ = Plot::Speed;
    bool allBalls_ = false;
    int selectedBall_ = -1;
    int selectedEvent_ = -1;
    double time_ = 0.0;
    std::vector<Line> lines_;

    QComboBox* plotBox_ = nullptr;
    QComboBox* ballsBox_ = nullptr;
    QLabel* hint_ = nullptr;
    PlotsChartView* view_ = nullptr;
};

}  // namespace cuelab
