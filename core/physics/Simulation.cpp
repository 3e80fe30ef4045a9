// SCAFFOLDING (foundation commit): returns the balls as set up, without motion or events.
// The event-based simulator of issue 3 replaces this file.
#include "Simulation.h"

namespace cuelab {

BallState SimulationResult::stateAt(int index, double t) const
{
    const auto& timeline = timelines.at(static_cast<std::size_t>(index));
    BallState s = timeline.front().state;
    for (const MotionSegment& seg : timeline)
        if (seg.start <= t) s = seg.state;
    return s;
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

SimulationResult simulate(const Setup& setup, const SimulationOptions&)
{
    SimulationResult r;
    r.table = makeTable(setup.table);
    r.physics = setup.physics;
    r.balls = setup.balls;
    for (const Ball& b : setup.balls) r.timelines.push_back({MotionSegment{0.0, b.state}});
    return r;
}

}  // namespace cuelab
