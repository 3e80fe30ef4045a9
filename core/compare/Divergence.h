#pragma once
// How far an engine's run strays from the exact run of the same setup (issue 9).
//
// Both runs are sampled at the same times k * sampleDt; a run that ends (all at rest) before the
// other keeps its last state, and a run stopped by the time limit ends the comparison. A pocketed ball stands at its pocket's centre, so two runs that sink a
// ball in the same pocket agree on it, and a ball sunk in one run but not the other is as far off as
// the pocket is from where the other left it.

#include "Engine.h"

#include <optional>
#include <vector>

namespace cuelab::compare {

struct EventTimeDifference {
    int index = 0;            // position in both collision lists (they agree up to here)
    double exactTime = 0.0;   // s
    double engineTime = 0.0;  // s
    double difference() const { return engineTime - exactTime; }
};

struct Divergence {
    std::vector<double> times;               // s, the common sample times
    std::vector<std::vector<double>> error;  // error[ball][k]: m, |engine - exact| at times[k]
    double maxError = 0.0;                   // m, the largest over balls and times
    int maxErrorBall = -1;                   // its ball (-1 without balls)
    double maxErrorTime = 0.0;               // s, and when
    std::vector<double> finalError;          // m, per ball at the last common sample time
    std::vector<EventTimeDifference> matched;      // the matching collisions, in order
    double maxEventTimeDifference = 0.0;     // s, the largest |difference| among them
    std::optional<int> firstSequenceDifference;    // the first index where the collision lists
                                                   // differ (kind, balls, cushion or pocket, or one
                                                   // list ending first); nullopt when equal
    double worstOverlap = 0.0;               // m, the engine's deepest ball-ball overlap
};

// Two collisions match when they have the same kind, the same balls and the same cushion or pocket.
bool sameCollision(const Collision& a, const Collision& b);

// The measures of `run` against `exact` (the same setup: same balls in the same order).
Divergence measureDivergence(const EngineRun& exact, const EngineRun& run);

// One setup under one engine beside its exact run.
struct Comparison {
    EngineRun exact;
    EngineRun run;
    Divergence divergence;
};

// Runs the exact engine (with the settings' sample step) and `settings`' engine, and measures them.
// `progress` sees the engine's simulated time (the exact run is quick); cancelling leaves
// run.cancelled set and the divergence empty.
Comparison compareEngines(const Setup& setup, const EngineSettings& settings, const Progress& progress = {});

// compareEngines in its two parts, for a caller that reports progress or stops in between (the
// window's CompareRunner): the exact run sampled on `settings`' sample step, then the comparison
// with that exact run. compareEngines(s, e, p) == compareWith(s, e, exactRunFor(s, e), p).
EngineRun exactRunFor(const Setup& setup, const EngineSettings& settings, const Progress& progress = {});
Comparison compareWith(const Setup& setup, const EngineSettings& settings, EngineRun exact, const Progress& progress = {});

}  // namespace cuelab::compare
