#pragma once
// The events of a simulation result as a table: index, time, kind, agents, time since the previous
// event, and the values that matter for the kind (relative speed and impulse for collisions, the
// cushion or pocket hit, the speed at a change of motion).

#include "Simulation.h"

#include <QAbstractTableModel>

#include <memory>

namespace cuelab {

class EventTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { IndexColumn, TimeColumn, KindColumn, AgentsColumn, GapColumn, DetailsColumn, ColumnCount };

    explicit EventTableModel(QObject* parent = nullptr);

    void setResult(std::shared_ptr<const SimulationResult> result);
    void setTime(double seconds);  // events after it are shown dimmed
    const Event* event(int row) const;  // null outside the rows

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    // Short description of an event's agents and key values, shared with the inspector.
    static QString agents(const SimulationResult& result, const Event& event);
    static QString details(const SimulationResult& result, const Event& event);

private:
    std::shared_ptr<const SimulationResult> result_;
    double time_ = 0.0;  // s
};

}  // namespace cuelab
