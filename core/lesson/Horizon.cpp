#include "Horizon.h"

#include <algorithm>

namespace cuelab::lesson {

SimulationResult shownBefore(const SimulationResult& whole, double horizon)
{
    if (!(horizon < whole.endTime)) return whole;
    SimulationResult shown;
    shown.table = whole.table;
    shown.physics = whole.physics;
    shown.balls = whole.balls;
    // Events are in time order (Simulation.h): the ones before the horizon are a prefix.
    const auto firstHidden = std::find_if(whole.events.begin(), whole.events.end(), [horizon](const Event& e) { return e.time >= horizon; });
    shown.events.assign(whole.events.begin(), firstHidden);
    shown.timelines.reserve(whole.timelines.size());
    for (const std::vector<MotionSegment>& timeline : whole.timelines) {
        auto end = std::find_if(timeline.begin(), timeline.end(), [horizon](const MotionSegment& s) { return s.start >= horizon; });
        if (end == timeline.begin() && end != timeline.end()) ++end;  // every ball keeps where it starts
        shown.timelines.emplace_back(timeline.begin(), end);
    }
    shown.endTime = std::max(0.0, horizon);
    // What simulate() says of a run asked to stop at a time with balls still moving. A run that never
    // finished (cut short, cancelled) keeps saying so.
    shown.status = whole.finished() ? SimulationStatus::ReachedUntil : whole.status;
    shown.error = whole.error;
    return shown;
}

}  // namespace cuelab::lesson
