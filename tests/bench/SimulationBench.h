#pragma once
// Speed of the simulator: the 15-ball break, and events per second as the ball count grows.

#include <vector>

namespace cuelab::bench {

struct BreakFigures {
    double msMedian = 0.0;  // ms per simulate() of the whole break, median over the runs
    double msMin = 0.0;
    long long events = 0;   // events of one break (every run is identical)
    int runs = 0;
};

// A frozen 8-ball rack broken from the head spot on a 9-ft table with the cue ball leaving at 8 m/s,
// simulated until every ball rests, `runs` times.
BreakFigures runBreakBench(int runs);

struct ScalingPoint {
    int balls = 0;
    double eventsPerSecond = 0.0;  // logged events per second of processor time, over 8 layouts
};

// `balls` balls, all moving at t = 0 with random velocities and spins, on a closed table whose sides
// grow with sqrt(balls / 16) from the 9-ft size (the same density), simulated until they rest.
ScalingPoint runScalingBench(int balls);

}  // namespace cuelab::bench
