// The explanation's record of held groups (ContactTrace.h): the end of a traced settle(), and the
// run again of a result that records them. Nothing here runs in a normal simulation.

#include "ContactTrace.h"
#include "Simulator.h"

namespace cuelab {

namespace detail {

void Simulator::recordHeldTrace(HeldGroupTrace& trace, int event, bool seated, const std::vector<ContactBall>& balls,
                                const std::vector<char>& heldRows, const std::vector<char>& kept, const std::vector<char>& idle)
{
    if (event < 0) return;  // (a group solved again with no event: nothing to explain)
    trace.event = event;
    trace.seated = seated;
    trace.seatedStates = balls;
    trace.rolledOut.resize(balls.size(), 0);
    for (std::size_t k = 0; k < trace.rows.size(); ++k) {
        HeldRow& row = trace.rows[k];
        row.pressed = k < trace.pressedForces.active.size() && trace.pressedForces.active[k];
        row.kept = k < kept.size() && kept[k];
        if (row.kept) trace.keptRows.push_back(static_cast<int>(k));
    }
    if (trace.seating.bilateral.size() == heldRows.size() && trace.seatingTries < 3)
        trace.seating.bilateral = heldRows;  // (the held rows the re-seating kept at w = 0)
    for (std::size_t m = 0; m < trace.members.size(); ++m) {
        const int b = trace.members[m];
        trace.push.push_back(push_[at(b)]);
        trace.pushZ.push_back(pushZ_[at(b)]);
        // (A member the solve left alone keeps its segment, begun earlier: its state now.)
        trace.after.push_back(idle[m] ? stateNow(b, trace.time) : state_[at(b)]);
    }
    if (heldTrace_->event >= 0 && heldTrace_->event != event) return;
    if (!heldTrace_->traces.empty() && heldTrace_->traces.back().event == event)
        heldTrace_->traces.back() = std::move(trace);
    else
        heldTrace_->traces.push_back(std::move(trace));
    heldTrace_->done = heldTrace_->event >= 0;
}

}  // namespace detail

namespace {

bool sameState(const BallState& a, const BallState& b)
{
    return a.position == b.position && a.velocity == b.velocity && a.spin == b.spin && a.motion == b.motion &&
           a.z == b.z && a.vz == b.vz;
}

bool sameEvent(const Event& a, const Event& b)
{
    return a.kind == b.kind && a.time == b.time && a.balls == b.balls && sameState(a.before[0], b.before[0]) &&
           sameState(a.after[0], b.after[0]) && sameState(a.before[1], b.before[1]) && sameState(a.after[1], b.after[1]);
}

// The run again up to `last` (every event's traces when `only` < 0), with each way the strike may
// have been set up (SimulationOptions::strikeKeepsElevation): the one that gives the result's events.
bool runAgain(const SimulationResult& result, const std::optional<CueStrike>& shot, std::size_t last, int only,
              HeldTraceSink& sink)
{
    for (bool elevation : {true, false}) {
        SimulationResult again;
        again.table = result.table;
        again.physics = result.physics;
        again.balls = result.balls;
        SimulationOptions options;
        options.strikeKeepsElevation = elevation;
        options.maxEvents = static_cast<long long>(result.events.size()) + 1;
        sink = HeldTraceSink{};
        sink.event = only;
        detail::Simulator sim(again, result.events[last].time, options);
        sim.traceHeld(&sink);
        sim.run(shot);
        if (again.events.size() <= last) continue;
        bool same = true;
        for (std::size_t k = only < 0 ? 0 : last; k <= last && same; ++k) same = sameEvent(again.events[k], result.events[k]);
        if (same) return true;
    }
    return false;
}

}  // namespace

std::optional<HeldGroupTrace> traceHeldGroup(const SimulationResult& result, int index, const std::optional<CueStrike>& shot)
{
    if (index < 0 || static_cast<std::size_t>(index) >= result.events.size()) return std::nullopt;
    HeldTraceSink sink;
    if (!runAgain(result, shot, static_cast<std::size_t>(index), index, sink) || sink.traces.empty()) return std::nullopt;
    return std::move(sink.traces.front());
}

std::vector<HeldGroupTrace> traceHeldGroups(const SimulationResult& result, const std::optional<CueStrike>& shot)
{
    HeldTraceSink sink;
    if (result.events.empty() || !runAgain(result, shot, result.events.size() - 1, -1, sink)) return {};
    return std::move(sink.traces);
}

}  // namespace cuelab
