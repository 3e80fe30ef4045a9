#pragma once
// The events of a result as the Events dock lists them: filtered (by kind, by ball, by the least
// relative speed of a collision), and grouped by instant, so that the chain of simultaneous
// collisions through a frozen rack is one expandable row. Columns as EventTableModel's; a group row
// sums its events up. Events after the current time are dimmed, the current one is bold.

#include "EventTableModel.h"

#include "Simulation.h"

#include <QAbstractItemModel>

#include <memory>
#include <vector>

namespace cuelab {

struct EventFilter {
    enum class Kinds {
        All,
        NoChangesOfMotion,  // strikes, collisions and pockets
        Collisions,         // ball-ball, cushions and jaws
        BallBall,
        Cushions,           // cushions and jaws
        Pockets,
        Strikes,
        ChangesOfMotion,
    };
    Kinds kinds = Kinds::All;
    int ball = -1;          // only events this ball takes part in; -1 = every ball
    double minSpeed = 0.0;  // m/s: collisions with a smaller normal approach speed are hidden

    bool accepts(const Event& e) const;
    bool operator==(const EventFilter&) const = default;
};

class EventTreeModel : public QAbstractItemModel {
    Q_OBJECT
public:
    using Column = EventTableModel::Column;

    explicit EventTreeModel(QObject* parent = nullptr);

    void setResult(std::shared_ptr<const SimulationResult> result);
    const std::shared_ptr<const SimulationResult>& result() const { return result_; }
    void setFilter(const EventFilter& filter);
    const EventFilter& filter() const { return filter_; }
    void setTime(double seconds);
    // The event that decides the shot's verdict (issue 43): its row carries a flag and `note` as its
    // tooltip; -1 marks none.
    void setMarkedEvent(int event, const QString& note);
    int markedEvent() const { return marked_; }

    // The event a row stands for: its index in the result; a group row stands for its first event.
    // -1 for an invalid index.
    int eventAt(const QModelIndex& index) const;
    // The row of an event: a child row when it is in a group, a top-level row otherwise; invalid
    // when the filter hides it.
    QModelIndex indexOfEvent(int event, int column = 0) const;
    // The last listed event at or before `seconds` (-1 when none): the one the list follows.
    int currentEvent() const { return current_; }
    bool isGroup(const QModelIndex& index) const;
    int listedEventCount() const;

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    void rebuild();  // groups from the result and the filter
    int findCurrent() const;
    QVariant eventData(int event, int column, int role) const;
    QVariant groupData(const std::vector<int>& group, int column, int role) const;
    double timeOf(int event) const { return result_->events[static_cast<std::size_t>(event)].time; }

    std::shared_ptr<const SimulationResult> result_;
    EventFilter filter_;
    std::vector<std::vector<int>> groups_;  // listed events by instant, in time order
    std::vector<int> groupOf_;              // per result event: its group, or -1 when hidden
    EventTableModel flat_;                  // the per-event texts
    double time_ = 0.0;                     // s
    int marked_ = -1;                       // the verdict's deciding event, -1 none
    QString markedNote_;
    int current_ = -1;
};

}  // namespace cuelab
