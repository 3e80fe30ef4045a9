// The simulator's public entry points (Simulation.h): simulate(), and the result's exact states.
// The event loop itself is in Simulator.cpp.

#include "Simulation.h"

#include "BounceSeries.h"
#include "Flight.h"
#include "Motion.h"
#include "Simulator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cuelab {

BallState SimulationResult::stateAt(int index, double t) const
{
    // A time that is not finite has no state (NaN fails every comparison of the search below, and
    // evolving by an infinite span gives NaN): refused like a bad index.
    if (!std::isfinite(t)) throw std::domain_error("SimulationResult::stateAt: the time is not a finite number");
    const std::vector<MotionSegment>& timeline = timelines.at(static_cast<std::size_t>(index));
    const double R = balls.at(static_cast<std::size_t>(index)).radius;
    // The last segment starting at or before t: at an event time, the state just after it.
    auto it = std::upper_bound(timeline.begin(), timeline.end(), t,
                               [](double time, const MotionSegment& s) { return time < s.start; });
    if (it != timeline.begin()) --it;
    if (it->pushed()) return segmentState(*it, R, physics, t - it->start);  // a held push or flight
    BallState s = it->state;
    double start = it->start;
    if (it->bounces) {  // a bounce series, then the cloth's motion from its end
        const BounceSeries b = bounceSeriesOf(it->state, R, physics);
        if (t - it->start < b.duration) return seriesStateAt(b, t - it->start);
        s = b.end;
        start = it->start + b.duration;
    }
    // Past the run's end (a time limit) the ball carries on through its transitions, collision-free.
    for (;;) {
        const Transition tr = nextTransition(s, R, physics);
        if (tr.after == kNever || start + tr.after > t) break;
        s = applyTransition(s, R, physics);
        start += tr.after;
    }
    return evolve(s, R, physics, t - start);
}

BounceSeries bounceSeriesOf(const BallState& landing, double radius, const PhysicsParams& p)
{
    return bounceSeries(landing, radius, 1.0, p);
}

BallState segmentState(const MotionSegment& seg, double radius, const PhysicsParams& p, double dt)
{
    if (seg.bounces) return seriesStateAt(bounceSeriesOf(seg.state, radius, p), std::max(0.0, dt));
    if (seg.state.motion == MotionState::Airborne && seg.pushed())
        return flyHeld(seg.state, p.gravity, Vec3(seg.push.x(), seg.push.y(), seg.pushZ), dt);
    return evolve(seg.state, radius, p, dt, seg.push);
}

std::vector<BallState> SimulationResult::statesAt(double t) const
{
    std::vector<BallState> out;
    out.reserve(balls.size());
    for (std::size_t i = 0; i < balls.size(); ++i) out.push_back(stateAt(static_cast<int>(i), t));
    return out;
}

int SimulationResult::ballIndex(const std::string& id) const
{
    for (std::size_t i = 0; i < balls.size(); ++i)
        if (balls[i].id == id) return static_cast<int>(i);
    return -1;
}

SimulationResult simulate(const Setup& setup, const SimulationOptions& options)
{
    SimulationResult r;
    r.table = makeTable(setup.table);
    r.physics = setup.physics;
    r.balls = setup.balls;
    const double limit = options.until >= 0.0 ? std::min(options.until, setup.simulation.maxTime)
                                              : setup.simulation.maxTime;
    r.events.reserve(64 + 16 * setup.balls.size());
    detail::Simulator sim(r, limit, options);
    sim.run(setup.shot);
    return r;
}

}  // namespace cuelab