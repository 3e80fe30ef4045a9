#pragma once
// The simulator: simulate(setup) -> SimulationResult, deterministic and pure.
// The result holds the event log and, per ball, the piecewise closed-form motion between events, so
// the exact state of every ball at any time t is available without re-integrating.

#include "Ball.h"
#include "Event.h"
#include "Setup.h"
#include "Table.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cuelab {

enum class SimulationStatus : std::uint8_t {
    AllAtRest,     // every ball is stationary or pocketed at endTime
    ReachedUntil,  // stopped at the requested time limit (until or maxTime) with balls still moving
    EventLimit,    // too many events: the run was cut short (error holds a message)
};

struct SimulationOptions {
    double until = -1.0;          // s; < 0: run until rest or Setup::simulation.maxTime
    long long maxEvents = 200000; // a cap that ends a pathological run with an error instead of a hang
};

// A stretch of a ball's motion: from `start` on, the ball moves in closed form from `state`
// (sliding, rolling, spinning, ...) until the next segment's start.
struct MotionSegment {
    double start = 0.0;  // s
    BallState state;     // the state at `start`, just after whatever event began the segment
};

class SimulationResult {
public:
    Table table;
    PhysicsParams physics;
    std::vector<Ball> balls;  // the balls as set up, before the cue strike
    std::vector<Event> events;
    std::vector<std::vector<MotionSegment>> timelines;  // per ball, sorted by start
    double endTime = 0.0;     // s, when the last ball came to rest (or the time limit)
    SimulationStatus status = SimulationStatus::AllAtRest;
    std::string error;        // set when status == EventLimit

    // The exact state of ball `index` at time t (at an event time: the state just after the event).
    BallState stateAt(int index, double t) const;
    std::vector<BallState> statesAt(double t) const;
    int ballIndex(const std::string& id) const;  // -1 if unknown
};

SimulationResult simulate(const Setup& setup, const SimulationOptions& options = {});

}  // namespace cuelab
