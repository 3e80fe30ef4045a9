#pragma once
// 1-D tolerance scans: how far one parameter of a shot may stray from its current value while the
// shot still meets its goal. A grid around the current value finds the window of successes that
// holds the current value (or, when the current shot fails, the window nearest to it); bisection
// then refines each edge of the window between the last success and the first failure.

#include "Sweep.h"

#include <functional>
#include <stop_token>
#include <string>
#include <vector>

namespace cuelab::analysis {

struct ToleranceRequest {
    double halfSpan = 1.0;  // scan [current - halfSpan, current + halfSpan], in the key's unit
    int count = 41;         // grid points (odd keeps the current value on the grid)
    int refineSteps = 20;   // bisection steps per edge: the edge is known to halfSpan * 2 / (count - 1) / 2^steps
    // The scan is clipped to the values the setup can take at all (an elevation below 0 is refused
    // anyway; clipping keeps the grid on legal values).
    double lowest = -1e300, highest = 1e300;
};

struct ToleranceScan {
    std::string key;
    double current = 0.0;
    std::vector<double> values;   // the grid
    std::vector<ShotStatus> status;
    std::vector<bool> met;        // per grid value
    bool currentMet = false;
    bool found = false;           // some grid value meets the goal
    double low = 0.0, high = 0.0; // the refined window (when found)
    bool lowAtScanEdge = false, highAtScanEdge = false;  // the window runs past the scanned range
    long long shots = 0;          // simulations run

    double width() const { return high - low; }
    // Half the width: "±0.33°" when the window is about symmetric.
    double halfWidth() const { return (high - low) / 2.0; }
};

// Scans `parameter` of `spec.base` (spec.variations is ignored; spec.goal is the goal). Progress is
// reported as (done, total) from the calling thread; `stop` cancels (the result then has found = false).
ToleranceScan scanTolerance(const SweepSpec& spec, const Parameter& parameter, const ToleranceRequest& request,
                            std::stop_token stop = {},
                            const std::function<void(long long done, long long total)>& progress = {});

// The unit of a key for people: "°", "m/s", "R" (tip offsets), "m", "kg", "rad/s", "s", "".
std::string unitOf(const std::string& key);

// "from 10.21° to 10.87°, ±0.33°" with `digits` decimals; "(window reaches the scan's end)" when so.
std::string describeWindow(const ToleranceScan& scan, int digits);

}  // namespace cuelab::analysis
