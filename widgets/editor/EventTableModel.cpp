#include "EventTableModel.h"

#include "i18n/DisplayNames.h"
#include "Quantities.h"

#include <QBrush>
#include <QGuiApplication>
#include <QPalette>

namespace cuelab {

namespace {
constexpr int kTimeDecimals = 6;  // µs: event times are exact, show enough of them to tell events apart

QString ballName(const SimulationResult& result, int index)
{
    if (index < 0 || index >= static_cast<int>(result.balls.size())) return QStringLiteral("?");
    return QString::fromStdString(result.balls[static_cast<std::size_t>(index)].id);
}
}  // namespace

EventTableModel::EventTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void EventTableModel::setResult(std::shared_ptr<const SimulationResult> result)
{
    beginResetModel();
    result_ = std::move(result);
    endResetModel();
}

void EventTableModel::setTime(double seconds)
{
    if (seconds == time_) return;
    time_ = seconds;
    if (rowCount() > 0) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1), {Qt::ForegroundRole});
}

const Event* EventTableModel::event(int row) const
{
    return row >= 0 && row < rowCount() ? &result_->events[static_cast<std::size_t>(row)] : nullptr;
}

int EventTableModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() || !result_ ? 0 : static_cast<int>(result_->events.size());
}

int EventTableModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QString EventTableModel::agents(const SimulationResult& result, const Event& e)
{
    QString text = ballName(result, e.balls[0]);
    const Table& table = result.table;
    const auto name = [](const auto& list, int i) {
        // As a person reads it ("top-right pocket", translated), not the file's id ("pocket-tr").
        return i >= 0 && i < static_cast<int>(list.size()) ? displayElementName(list[static_cast<std::size_t>(i)].id)
                                                           : QStringLiteral("?");
    };
    switch (e.kind) {
    case EventKind::BallBall: text += QStringLiteral(" – ") + ballName(result, e.balls[1]); break;
    case EventKind::BallCushion: text += QStringLiteral(" – ") + name(table.cushions, e.cushion); break;
    case EventKind::BallJaw: text += QStringLiteral(" – ") + name(table.jaws, e.jaw); break;
    case EventKind::BallPocket: text += QStringLiteral(" → ") + name(table.pockets, e.pocket); break;
    default: break;
    }
    return text;
}

QString EventTableModel::details(const SimulationResult&, const Event& e)
{
    if (isCollision(e.kind)) {
        const QString values = QObject::tr("v_rel %1, |J| %2")
                                   .arg(formatQuantity(e.approachSpeed, QStringLiteral("m/s"), 3),
                                        formatQuantity(e.impulse.norm(), QStringLiteral("N·s"), 4));
        // A collision that begins a push (Contact.h: the pair is held in contact from here).
        return e.held ? values + QObject::tr(", held (a push)") : values;
    }
    if (e.kind == EventKind::CueStrike)
        return QObject::tr("v %1").arg(formatQuantity(e.after[0].velocity.norm(), QStringLiteral("m/s"), 3));
    if (e.kind == EventKind::BallPocket)
        return QObject::tr("at %1").arg(formatQuantity(e.before[0].velocity.norm(), QStringLiteral("m/s"), 3));
    // A change of motion: the speed it happens at (zero when the ball stops).
    return QObject::tr("v %1").arg(formatQuantity(e.after[0].velocity.norm(), QStringLiteral("m/s"), 3));
}

QVariant EventTableModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || !result_) return {};
    const std::size_t row = static_cast<std::size_t>(index.row());
    const Event& e = result_->events[row];
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case IndexColumn: return eventNumber(index.row());
        case TimeColumn: return formatNumber(e.time, kTimeDecimals);
        case KindColumn: return displayName(e.kind);
        case AgentsColumn: return agents(*result_, e);
        case GapColumn: return row == 0 ? QStringLiteral("–") : formatNumber(e.time - result_->events[row - 1].time, kTimeDecimals);
        case DetailsColumn: return details(*result_, e);
        default: return {};
        }
    }
    if (role == Qt::ToolTipRole && index.column() == DetailsColumn) return details(*result_, e);
    if (role == Qt::TextAlignmentRole && (index.column() == IndexColumn || index.column() == TimeColumn || index.column() == GapColumn))
        return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ForegroundRole && e.time > time_ + 1e-12)  // not happened yet at the current time
        return QBrush(QGuiApplication::palette().color(QPalette::Disabled, QPalette::Text));
    return {};
}

QVariant EventTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal) return {};
    if (role == Qt::DisplayRole) {
        switch (section) {
        case IndexColumn: return QStringLiteral("#");
        case TimeColumn: return tr("Time (s)");
        case KindColumn: return tr("Kind");
        case AgentsColumn: return tr("Agents");
        case GapColumn: return tr("Δt (s)");
        case DetailsColumn: return tr("Key values");
        default: return {};
        }
    }
    if (role == Qt::ToolTipRole) {
        switch (section) {
        case TimeColumn: return tr("Time of the event in seconds after the strike (exact: a root of a polynomial)");
        case GapColumn: return tr("Seconds since the previous event");
        case DetailsColumn: return tr("Collisions: normal approach speed (m/s) and impulse (N·s); changes of motion: speed after (m/s)");
        default: return {};
        }
    }
    return {};
}

}  // namespace cuelab
