#include "RunState.h"

#include "Quantities.h"
#include "Simulation.h"

#include <QLocale>

namespace cuelab {

namespace {

QString count(long long n) { return QLocale().toString(static_cast<qlonglong>(n)); }

}  // namespace

QString RunState::simulatingText(long long events, double time)
{
    return tr("Simulating… %1 events, t = %2").arg(count(events), formatQuantity(time, QStringLiteral("s"), 3));
}

QString RunState::withheldNote(double horizon)
{
    return tr("Until the reveal: the shot up to t = %1").arg(formatQuantity(horizon, QStringLiteral("s"), 3));
}

QString RunState::unfinishedNote(const SimulationResult& result)
{
    const QString at = formatQuantity(result.endTime, QStringLiteral("s"), 3);
    const long long events = static_cast<long long>(result.events.size());
    switch (result.status) {
    case SimulationStatus::AllAtRest:
    case SimulationStatus::ReachedUntil: return {};
    case SimulationStatus::Running: return tr("Simulating… %1 events so far, t = %2").arg(count(events), at);
    case SimulationStatus::Cancelled:
        return tr("Stopped at t = %1 (cancelled after %2 events): a partial result").arg(at, count(events));
    case SimulationStatus::EventLimit: return tr("Cut short at t = %1 (event limit reached): a partial result").arg(at);
    }
    return {};
}

}  // namespace cuelab
