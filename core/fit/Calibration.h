#pragma once
// Calibration: the values of shared physics keys (e.g. physics.mu_roll,
// physics.ball_cushion.restitution) that make many recordings follow their simulations best, each
// recording with its own strike (CONTRACT.md, `cuelab-cli calibrate`).
//
// Method (nested, in rounds):
//   round 1  every recording's strike is fitted (fitStrike, the whole schedule) with the shared
//            keys at their starting values;
//   outer    a derivative-free local search (LocalOptions::method, Subplex by default) over the
//            shared keys minimises the mean over the recordings of their residuals, where each
//            recording's residual at a trial of the shared keys is that of a local refit of its
//            strike (refitStrike) started from the strike of the round's fit. Starting every refit
//            from the round's strike, not from the last trial's, keeps the objective a function of
//            the shared values alone (no hidden state, so no dependence on the order or the threads).
//   round 2… the strikes are fitted again (the whole schedule, also from the last strike) at the
//            shared values found, and the outer search runs again from them; the rounds stop after
//            CalibrationOptions::rounds or when a round improves the mean residual by less than 1 %.
// Why nested and not alternating (strikes fixed, then the shared keys): the cue speed and the
// rolling resistance trade against each other along a narrow valley (a faster strike on a slower
// cloth reaches the same place), where alternating steps crawl; the refit lets the strike follow.
// The recordings of an outer trial are refitted in parallel (one per thread).

#include "StrikeFit.h"

#include <functional>
#include <stop_token>
#include <string>
#include <vector>

namespace cuelab::fit {

struct CalibrationProblem {
    std::string name;     // names the recording in messages and output ("3c-000.json")
    Setup setup;          // the strike's ball and starting values; its shared keys are overwritten
    Recording recording;
};

struct CalibrationOptions {
    FitOptions strike;                 // each recording's strike fit (its threads: see `threads`)
    LocalOptions inner{Method::Subplex, 150, 1e-3, 1e-5};  // each refit at an outer trial
    LocalOptions outer{Method::Subplex, 200, 1e-3, 1e-5};  // the search over the shared keys
    int rounds = 2;
    int threads = 0;                   // 0: every core (the recordings run in parallel)
};

struct CalibrationProgress {
    int round = 1;
    int outerEvaluations = 0;
    int recordingsDone = 0;   // of the current strike fits (round start)
    int recordings = 0;
    double meanRmse = 0.0;    // m, the best mean residual so far
};

struct CalibrationResult {
    std::vector<std::string> sharedKeys;
    std::vector<double> shared;          // calibrated, one per shared key
    std::vector<FitResult> fits;         // per recording, at the calibrated values
    double meanRmse = 0.0;               // m, mean of fits[i].rmse
    long long evaluations = 0;           // simulations in all
    double seconds = 0.0;
    bool cancelled = false;
};

// The shared keys resolve against the first problem's setup (their starting values and boxes) and
// are copied into every setup; the strike keys resolve against each setup.
CalibrationResult calibrate(const std::vector<CalibrationProblem>& problems, const std::vector<FitKey>& sharedKeys,
                            const std::vector<std::string>& strikeKeys, const CalibrationOptions& options = {},
                            const std::function<void(const CalibrationProgress&)>& progress = {},
                            std::stop_token stop = {});

}  // namespace cuelab::fit
