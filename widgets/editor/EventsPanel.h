#pragma once
// The Events dock: the event list of the current result, grouped by instant (a rack's chain of
// simultaneous collisions is one expandable row) and filtered by kind, ball and the least relative
// speed of a collision. It follows playback: the last event that has happened is bold and kept in
// view. Selecting a row asks the window to jump to that moment (eventSelected).

#include "Simulation.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QTreeView;

namespace cuelab {

struct EventFilter;
class EventTreeModel;

class EventsPanel : public QWidget {
    Q_OBJECT
public:
    explicit EventsPanel(QWidget* parent = nullptr);

    QTreeView* table() const { return table_; }
    EventTreeModel* model() const { return model_; }
    QComboBox* kindFilter() const { return kinds_; }
    QComboBox* ballFilter() const { return ball_; }
    QDoubleSpinBox* speedFilter() const { return minSpeed_; }
    int selectedEvent() const;   // index in the result's events; -1 = none
    int currentEvent() const;    // the event the list follows: the last listed one at or before the time
    void setFilter(const EventFilter& filter);  // as if chosen in the filter widgets

public slots:
    void setResult(std::shared_ptr<const SimulationResult> result);
    void setTime(double seconds);
    void setSelectedEvent(int index);  // -1 = none; does not emit eventSelected

signals:
    void eventSelected(int index);

private:
    void applyFilter();
    void fillBalls();
    void followCurrent();

    QTreeView* table_;
    EventTreeModel* model_;
    QComboBox* kinds_;
    QComboBox* ball_;
    QLabel* note_ = nullptr;  // a run still going, cancelled or cut short (issue 39)
    QDoubleSpinBox* minSpeed_;
    bool selecting_ = false;
};

}  // namespace cuelab
