#pragma once
// The Events dock: the event list of the current result. Selecting a row asks the window to jump to
// that moment (eventSelected).

#include "Simulation.h"

#include <QWidget>

#include <memory>

class QCheckBox;
class QSortFilterProxyModel;
class QTableView;

namespace cuelab {

class EventTableModel;

class EventsPanel : public QWidget {
    Q_OBJECT
public:
    explicit EventsPanel(QWidget* parent = nullptr);

    QTableView* table() const { return table_; }
    EventTableModel* model() const { return model_; }
    QCheckBox* transitionsToggle() const { return showTransitions_; }
    int selectedEvent() const;

public slots:
    void setResult(std::shared_ptr<const SimulationResult> result);
    void setTime(double seconds);
    void setSelectedEvent(int index);  // -1 = none; does not emit eventSelected

signals:
    void eventSelected(int index);

private:
    QTableView* table_;
    EventTableModel* model_;
    QSortFilterProxyModel* filter_;
    QCheckBox* showTransitions_;
    bool selecting_ = false;
};

}  // namespace cuelab
