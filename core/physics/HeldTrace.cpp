// The explanation's record of held groups (ContactTrace.h): the end of a traced settle(), and the
// run again of a result that records them. Nothing here runs in a normal simulation.

#include "ContactTrace.h"
#include "Simulator.h"

#include <algorithm>
#include <chrono>
#include <stop_token>

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
// The limits stop it through the simulator's own cancel token; the budget is checked in its progress
// callback, every few milliseconds of wall time.
HeldTraces runAgain(const SimulationResult& result, const std::optional<CueStrike>& shot, std::size_t last, int only,
                    const HeldTraceLimits& limits)
{
    using Clock = std::chrono::steady_clock;
    // (A budget beyond a day is none: the deadline would not fit the clock's range.)
    const bool timed = limits.seconds < 86400.0;
    const Clock::time_point deadline =
        timed ? Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double>(std::max(limits.seconds, 0.0)))
              : Clock::time_point::max();
    std::stop_source stop;
    const std::stop_callback forward(limits.stop, [&stop] { stop.request_stop(); });
    HeldTraces out;
    for (bool elevation : {true, false}) {
        if (limits.stop.stop_requested()) return HeldTraces{HeldTraceStatus::Cancelled, {}, -1};
        if (Clock::now() >= deadline) return HeldTraces{HeldTraceStatus::OutOfTime, {}, -1};
        SimulationResult again;
        again.table = result.table;
        again.physics = result.physics;
        again.balls = result.balls;
        SimulationOptions options;
        options.strikeKeepsElevation = elevation;
        // (The time limit ends it at the event. The event cap also caps the loop's steps, 50 per
        // event, and a shot whose held groups are solved again many times between events takes
        // more: the run again must have the room the first run had, or it stops short and differs,
        // seed41-shot1421's cluster at its event 164.)
        options.maxEvents = std::max(static_cast<long long>(result.events.size()) + 1, SimulationOptions{}.maxEvents);
        options.cancel = stop.get_token();
        if (timed) {
            options.progressInterval = 0.005;
            options.progress = [&](const SimulationResult&, const SimulationProgress&) {
                if (Clock::now() >= deadline) stop.request_stop();
            };
        }
        HeldTraceSink sink;
        sink.event = only;
        detail::Simulator sim(again, result.events[last].time, options);
        sim.traceHeld(&sink);
        sim.run(shot);
        const bool stopped = again.status == SimulationStatus::Cancelled && !sink.done;
        if (stopped && limits.stop.stop_requested()) return HeldTraces{HeldTraceStatus::Cancelled, {}, -1};
        if (stopped) {
            // The events it logged and gave bit for bit, but for the last (its group may have been
            // solved again at the same instant after the stop): their traces stand.
            out = HeldTraces{HeldTraceStatus::OutOfTime, {}, -1};
            if (only >= 0) return out;
            std::size_t same = 0;
            while (same + 1 < again.events.size() && same <= last && sameEvent(again.events[same], result.events[same])) ++same;
            out.covered = static_cast<int>(same) - 1;
            for (HeldGroupTrace& t : sink.traces)
                if (t.event <= out.covered) out.traces.push_back(std::move(t));
            if (out.covered >= 0) return out;  // (the strike reproduced: the other way need not be tried)
            continue;
        }
        if (again.events.size() <= last) continue;
        bool same = true;
        for (std::size_t k = only < 0 ? 0 : last; k <= last && same; ++k) same = sameEvent(again.events[k], result.events[k]);
        if (same) return HeldTraces{HeldTraceStatus::Recorded, std::move(sink.traces), static_cast<int>(last)};
    }
    return out;  // (Differs, or out of time with nothing reproduced)
}

}  // namespace

HeldTraces traceHeldGroup(const SimulationResult& result, int index, const std::optional<CueStrike>& shot,
                          const HeldTraceLimits& limits)
{
    if (index < 0 || static_cast<std::size_t>(index) >= result.events.size()) return {};
    HeldTraces out = runAgain(result, shot, static_cast<std::size_t>(index), index, limits);
    if (out.traces.size() > 1) out.traces.erase(out.traces.begin() + 1, out.traces.end());
    return out;
}

HeldTraces traceHeldGroups(const SimulationResult& result, int last, const std::optional<CueStrike>& shot,
                           const HeldTraceLimits& limits)
{
    if (last < 0 || static_cast<std::size_t>(last) >= result.events.size()) return {};
    return runAgain(result, shot, static_cast<std::size_t>(last), -1, limits);
}

}  // namespace cuelab
