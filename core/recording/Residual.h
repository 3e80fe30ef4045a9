#pragma once
// The residual of a simulation against a recording (PHYSICS.md, "Reconstructing recorded shots"):
// the root mean square of the distances between each recorded sample and the simulated centre at the
// sample's time, from the simulator's exact state (SimulationResult::stateAt), over the struck ball,
// the balls that moved, or every ball; per ball; and sample by sample over time.

#include "Recording.h"
#include "Simulation.h"

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace cuelab {

// Which balls a residual pools.
enum class BallSelection : std::uint8_t {
    Struck,  // the struck ball alone (the setup's shot ball; every ball when there is no shot)
    Moved,   // the balls that moved in the recording (Recording.h: moved), and the struck ball
    All,     // every recorded ball
};

struct ResidualOptions {
    BallSelection balls = BallSelection::Moved;
    double until = std::numeric_limits<double>::infinity();  // s; only samples at t <= until count
    bool keepSamples = false;  // fill Residual::samples (the plot over time); the fit leaves it off
    // s, the recording's time of the simulation's t = 0 (the cue strike): tracking may begin a frame
    // before the strike (or after it). A sample at recording time t is compared with the simulated
    // state at max(0, t - strikeTime).
    double strikeTime = 0.0;
};

struct BallResidual {
    std::string id;
    double rmse = 0.0;  // m, over this ball's counted samples (0 when none)
    int count = 0;      // samples counted
    bool selected = false;  // pooled into Residual::rmse
};

struct SampleResidual {
    double time = 0.0;      // s
    int ball = 0;           // index into Recording::balls
    Vec2 recorded = Vec2::Zero();
    Vec2 simulated = Vec2::Zero();
    double distance = 0.0;  // m
};

struct Residual {
    double rmse = 0.0;  // m, pooled over the selected balls' samples
    int count = 0;      // samples pooled
    std::vector<BallResidual> perBall;     // every recorded ball, in the recording's order
    std::vector<SampleResidual> samples;   // when asked for: every counted sample, ball by ball
};

// Which recorded balls a selection pools. `struckId` names the struck ball ("" when none).
std::vector<bool> selectedBalls(const Recording& recording, const std::string& struckId, BallSelection balls);

// The residual of `result` (a run of a setup holding every recorded ball by id) against `recording`.
// A recorded ball missing from the simulation counts as infinitely far (rmse = +inf): a caller
// checks ids first (missingBall). Simulated positions beyond the run's end are the resting states.
Residual residual(const SimulationResult& result, const Recording& recording, const std::string& struckId,
                  const ResidualOptions& options = {});

// The residual sample by sample as CSV (a header line, then one line per sample of `r.samples`, ball by
// ball): ball id, time (s), recorded x and y, simulated x and y (m), distance (m); numbers with 17
// significant digits, a ball missing from the simulation as "inf".
std::string residualCsv(const Residual& r, const Recording& recording);

// The first recorded ball id that `setup` lacks, "" when every one is there.
std::string missingBall(const Recording& recording, const Setup& setup);

}  // namespace cuelab
