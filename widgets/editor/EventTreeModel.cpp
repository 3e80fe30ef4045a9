#include "EventTreeModel.h"

#include "FrameTimes.h"
#include "Quantities.h"
#include "i18n/DisplayNames.h"

#include <QFont>

#include <algorithm>
#include <set>

namespace cuelab {

namespace {

// A top-level row has internal id 0; a child row has its group's index + 1.
constexpr quintptr kTopLevel = 0;

// Events within this of a group's first event happen at the same instant: a frozen rack passes the
// strike on through its balls at one time, up to the rounding of the roots.
constexpr double kSameInstant = kSameMoment;  // s

bool isCushion(EventKind k) { return k == EventKind::BallCushion || k == EventKind::BallJaw; }

}  // namespace

bool EventFilter::accepts(const Event& e) const
{
    switch (kinds) {
    case Kinds::All: break;
    case Kinds::NoChangesOfMotion:
        if (isTransition(e.kind)) return false;
        break;
    case Kinds::Collisions:
        if (!isCollision(e.kind)) return false;
        break;
    case Kinds::BallBall:
        if (e.kind != EventKind::BallBall) return false;
        break;
    case Kinds::Cushions:
        if (!isCushion(e.kind)) return false;
        break;
    case Kinds::Pockets:
        if (e.kind != EventKind::BallPocket) return false;
        break;
    case Kinds::Strikes:
        if (e.kind != EventKind::CueStrike) return false;
        break;
    case Kinds::ChangesOfMotion:
        if (!isTransition(e.kind)) return false;
        break;
    }
    if (ball >= 0 && e.balls[0] != ball && !(e.kind == EventKind::BallBall && e.balls[1] == ball)) return false;
    if (minSpeed > 0.0 && isCollision(e.kind) && e.approachSpeed < minSpeed) return false;
    return true;
}

EventTreeModel::EventTreeModel(QObject* parent) : QAbstractItemModel(parent) {}

void EventTreeModel::setResult(std::shared_ptr<const SimulationResult> result)
{
    beginResetModel();
    result_ = std::move(result);
    flat_.setResult(result_);
    if (filter_.ball >= 0 && (!result_ || filter_.ball >= static_cast<int>(result_->balls.size()))) filter_.ball = -1;
    rebuild();
    endResetModel();
}

void EventTreeModel::setFilter(const EventFilter& filter)
{
    if (filter == filter_) return;
    beginResetModel();
    filter_ = filter;
    rebuild();
    endResetModel();
}

void EventTreeModel::rebuild()
{
    groups_.clear();
    groupOf_.clear();
    if (result_) {
        groupOf_.assign(result_->events.size(), -1);
        for (int i = 0; i < static_cast<int>(result_->events.size()); ++i) {
            if (!filter_.accepts(result_->events[static_cast<std::size_t>(i)])) continue;
            if (groups_.empty() || timeOf(i) - timeOf(groups_.back().front()) > kSameInstant) groups_.emplace_back();
            groups_.back().push_back(i);
            groupOf_[static_cast<std::size_t>(i)] = static_cast<int>(groups_.size()) - 1;
        }
    }
    current_ = findCurrent();
}

int EventTreeModel::findCurrent() const
{
    // The last listed event that has happened at the current time.
    for (auto g = groups_.rbegin(); g != groups_.rend(); ++g)
        if (timeOf(g->front()) <= time_ + 1e-12) return g->back();
    return -1;
}

void EventTreeModel::setTime(double seconds)
{
    if (seconds == time_) return;
    time_ = seconds;
    flat_.setTime(seconds);
    current_ = findCurrent();
    // Dimming and the bold current row: every visible row may change its look, not its text.
    const QList<int> roles{Qt::ForegroundRole, Qt::FontRole};
    if (!groups_.empty()) emit dataChanged(index(0, 0), index(static_cast<int>(groups_.size()) - 1, Column::ColumnCount - 1), roles);
    for (std::size_t g = 0; g < groups_.size(); ++g) {
        if (groups_[g].size() < 2) continue;
        const QModelIndex parent = index(static_cast<int>(g), 0);
        emit dataChanged(index(0, 0, parent), index(static_cast<int>(groups_[g].size()) - 1, Column::ColumnCount - 1, parent), roles);
    }
}

int EventTreeModel::eventAt(const QModelIndex& idx) const
{
    if (!idx.isValid() || idx.model() != this) return -1;
    if (idx.internalId() == kTopLevel) return groups_[static_cast<std::size_t>(idx.row())].front();
    return groups_[static_cast<std::size_t>(idx.internalId() - 1)][static_cast<std::size_t>(idx.row())];
}

QModelIndex EventTreeModel::indexOfEvent(int event, int column) const
{
    if (event < 0 || event >= static_cast<int>(groupOf_.size())) return {};
    const int g = groupOf_[static_cast<std::size_t>(event)];
    if (g < 0) return {};
    const std::vector<int>& group = groups_[static_cast<std::size_t>(g)];
    if (group.size() < 2) return index(g, column);
    const auto at = std::find(group.begin(), group.end(), event);
    return index(static_cast<int>(at - group.begin()), column, index(g, 0));
}

bool EventTreeModel::isGroup(const QModelIndex& idx) const
{
    return idx.isValid() && idx.internalId() == kTopLevel && groups_[static_cast<std::size_t>(idx.row())].size() > 1;
}

int EventTreeModel::listedEventCount() const
{
    int n = 0;
    for (const auto& g : groups_) n += static_cast<int>(g.size());
    return n;
}

QModelIndex EventTreeModel::index(int row, int column, const QModelIndex& parent) const
{
    if (row < 0 || column < 0 || column >= Column::ColumnCount) return {};
    if (!parent.isValid()) {
        if (row >= static_cast<int>(groups_.size())) return {};
        return createIndex(row, column, kTopLevel);
    }
    if (parent.internalId() != kTopLevel || parent.row() >= static_cast<int>(groups_.size())) return {};
    const std::vector<int>& group = groups_[static_cast<std::size_t>(parent.row())];
    if (group.size() < 2 || row >= static_cast<int>(group.size())) return {};
    return createIndex(row, column, static_cast<quintptr>(parent.row()) + 1);
}

QModelIndex EventTreeModel::parent(const QModelIndex& child) const
{
    if (!child.isValid() || child.internalId() == kTopLevel) return {};
    return createIndex(static_cast<int>(child.internalId() - 1), 0, kTopLevel);
}

int EventTreeModel::rowCount(const QModelIndex& parent) const
{
    if (!parent.isValid()) return static_cast<int>(groups_.size());
    if (parent.column() != 0 || parent.internalId() != kTopLevel) return 0;
    const std::vector<int>& group = groups_[static_cast<std::size_t>(parent.row())];
    return group.size() > 1 ? static_cast<int>(group.size()) : 0;
}

int EventTreeModel::columnCount(const QModelIndex&) const { return Column::ColumnCount; }

QVariant EventTreeModel::data(const QModelIndex& idx, int role) const
{
    if (!idx.isValid() || !result_) return {};
    if (idx.internalId() == kTopLevel) {
        const std::vector<int>& group = groups_[static_cast<std::size_t>(idx.row())];
        if (group.size() > 1) return groupData(group, idx.column(), role);
        return eventData(group.front(), idx.column(), role);
    }
    return eventData(eventAt(idx), idx.column(), role);
}

void EventTreeModel::setMarkedEvent(int event, const QString& note)
{
    if (event == marked_ && note == markedNote_) return;
    marked_ = event;
    markedNote_ = note;
    if (rowCount() > 0) emit dataChanged(index(0, 0), index(rowCount() - 1, Column::ColumnCount - 1));
}

QVariant EventTreeModel::eventData(int event, int column, int role) const
{
    if (role == Qt::FontRole && event == current_) {
        QFont font;
        font.setBold(true);
        return font;
    }
    // The verdict's deciding event: a flag after its number, the verdict as its tooltip.
    if (event == marked_ && marked_ >= 0 && column == Column::IndexColumn) {
        if (role == Qt::DisplayRole) return flat_.data(flat_.index(event, column), role).toString() + QStringLiteral(" \u2691");
        if (role == Qt::ToolTipRole) return markedNote_;
    }
    return flat_.data(flat_.index(event, column), role);
}

QVariant EventTreeModel::groupData(const std::vector<int>& group, int column, int role) const
{
    if (role == Qt::DisplayRole) {
        switch (column) {
        case Column::IndexColumn: {
            const QString numbers = QStringLiteral("%1–%2").arg(eventNumber(group.front()), eventNumber(group.back()));
            const bool marked = std::find(group.begin(), group.end(), marked_) != group.end();
            return marked ? numbers + QStringLiteral(" \u2691") : numbers;  // it holds the verdict's event
        }
        case Column::TimeColumn:
        case Column::GapColumn: return flat_.data(flat_.index(group.front(), column), role);
        case Column::KindColumn: {
            // "4 × ball-ball, 1 × ball-cushion"
            std::vector<std::pair<EventKind, int>> counts;
            for (int e : group) {
                const EventKind k = result_->events[static_cast<std::size_t>(e)].kind;
                auto it = std::find_if(counts.begin(), counts.end(), [k](const auto& c) { return c.first == k; });
                if (it == counts.end()) counts.emplace_back(k, 1);
                else ++it->second;
            }
            QStringList parts;
            for (const auto& [kind, n] : counts) parts << QStringLiteral("%1 × %2").arg(n).arg(displayName(kind));
            return parts.join(QStringLiteral(", "));
        }
        case Column::AgentsColumn: {
            std::set<int> balls;
            for (int e : group) {
                const Event& ev = result_->events[static_cast<std::size_t>(e)];
                balls.insert(ev.balls[0]);
                if (ev.kind == EventKind::BallBall) balls.insert(ev.balls[1]);
            }
            QStringList ids;
            for (int b : balls)
                if (b >= 0 && b < static_cast<int>(result_->balls.size()))
                    ids << QString::fromStdString(result_->balls[static_cast<std::size_t>(b)].id);
            return tr("%n ball(s): %1", nullptr, static_cast<int>(ids.size())).arg(ids.join(QStringLiteral(", ")));
        }
        case Column::DetailsColumn: {
            double fastest = 0.0;
            for (int e : group) {
                const Event& ev = result_->events[static_cast<std::size_t>(e)];
                if (isCollision(ev.kind)) fastest = std::max(fastest, ev.approachSpeed);
            }
            return tr("%n events at one instant", nullptr, static_cast<int>(group.size())) +
                   (fastest > 0.0 ? tr(", fastest v_rel %1").arg(formatQuantity(fastest, QStringLiteral("m/s"), 3)) : QString());
        }
        default: return {};
        }
    }
    if (role == Qt::ToolTipRole)
        return tr("%n events at the same instant (expand to see each)", nullptr, static_cast<int>(group.size()));
    if (role == Qt::FontRole && std::find(group.begin(), group.end(), current_) != group.end()) {
        QFont font;
        font.setBold(true);
        return font;
    }
    if (role == Qt::TextAlignmentRole || role == Qt::ForegroundRole)
        return flat_.data(flat_.index(group.front(), column), role);
    return {};
}

QVariant EventTreeModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    return flat_.headerData(section, orientation, role);
}

}  // namespace cuelab
