#pragma once
// The strike fit (PHYSICS.md, "Reconstructing recorded shots"): the values of some keys of a setup
// (by default the strike: heading, speed, side, height) that make its simulation follow a recording
// best, i.e. that minimise the residual (core/recording Residual.h) over the chosen balls.
//
// The residual is non-smooth (a collision appears or vanishes as the heading turns) and has many
// minima, so the fit is a schedule of derivative-free local searches (LocalSearch.h):
//   1. the first window (FitOptions::windows, 0.5 s by default) from several starts: the setup's
//      own values, and every combination of the headings, speeds and tip offsets around them in
//      FitOptions::headingStarts, speedStarts and tipStarts (the first half-second shows the heading and the
//      speed; the tips only begin to show);
//   2. each later window (2 s, 5 s, then the whole recording) from the `keep` results of the one before
//      that fit this window best (each result scored once over it), so that a search for the whole
//      run starts near the strikes the start of it showed.
//   3. the polish (FitOptions::polish): searches with ever smaller steps from the best.
// The local searches of a stage run in parallel, one per thread; each is a pure function of its
// start, and the best is chosen by value then by start index, so the result is the same for any
// thread count.

#include "FitKeys.h"
#include "LocalSearch.h"
#include "Recording.h"
#include "Residual.h"

#include "Setup.h"
#include "Simulation.h"

#include <functional>
#include <limits>
#include <stop_token>
#include <string>
#include <vector>

namespace cuelab::fit {

struct FitOptions {
    BallSelection balls = BallSelection::Moved;  // which balls the residual pools
    std::vector<double> windows{0.5, 2.0, 5.0};  // s; the whole recording is always the last window
    std::vector<double> tipStarts{-0.3, 0.0, 0.3};    // starting side and height (radii) of stage 1
    std::vector<double> headingStarts{-1.5, 0.0, 1.5};  // degrees around the setup's heading
    std::vector<double> speedStarts{0.85, 1.0, 1.2};     // factors of the setup's cue speed
    int keep = 8;                                // results of one stage that seed the next
    LocalOptions local;                          // each local search
    // Then, over the whole recording, searches from the best with first steps a tenth, a hundredth,
    // ... of the keys' steps, until one gains less than its residualTolerance.
    LocalOptions polish{Method::Bobyqa, 300, 1e-4, 1e-8};
    int polishRounds = 3;
    // Whether the recording's time of the strike (ResidualOptions::strikeTime) is fitted too, in
    // [-kStrikeTimeReach, kStrikeTimeReach]: tracked shots often begin a frame before the strike.
    bool fitStrikeTime = false;
    int threads = 0;                             // 0: every core
    long long maxEvents = 20000;                 // per simulation (a wild strike cannot hang a fit)
};

inline constexpr double kStrikeTimeReach = 0.1;  // s, five frames at 50 Hz

// What one residual measures: the balls, the window (recording time), the strike's time.
struct Measure {
    BallSelection balls = BallSelection::Moved;
    double until = std::numeric_limits<double>::infinity();  // s; infinity: the whole recording
    double strikeTime = 0.0;                                 // s (ResidualOptions::strikeTime)
    long long maxEvents = 20000;
};

// Progress of a fit, handed to the caller after each local search (from any thread, one at a time).
struct FitProgress {
    int searchesDone = 0;
    int searchesTotal = 0;   // grows as stages are planned
    long long evaluations = 0;
    double bestRmse = 0.0;   // m, the best residual of the current window so far
    // 0-1, the share of the fit's evaluation budget spent, a search that ended early credited with
    // its unspent budget: rises while any search runs (several times a second), 1 at the end.
    double fraction = 0.0;
};

struct FitResult {
    std::vector<std::string> keys;
    std::vector<double> values;  // fitted, one per key
    double strikeTime = 0.0;     // s, fitted when FitOptions::fitStrikeTime (else 0)
    Setup setup;                 // the base setup with the fitted values
    Residual residual;           // of the fitted setup over the whole recording (samples kept)
    double rmse = 0.0;           // m, residual.rmse (the chosen balls)
    double rmseStruck = 0.0;     // m, the struck ball alone
    double rmseAll = 0.0;        // m, every recorded ball
    long long evaluations = 0;   // simulations run
    double seconds = 0.0;        // wall-clock time of the fit
    bool cancelled = false;      // stopped early: the values are the best found so far
};

// The residual of `setup` against `recording` as the fit measures it: a setup the validator
// refuses, or a run cut short by the event cap, is `kRefusedResidual` metres off.
inline constexpr double kRefusedResidual = 100.0;  // m
double residualOf(const Setup& setup, const Recording& recording, const Measure& measure, Residual* out = nullptr);

// Fits `keys` of `base` to `recording`. The base setup must hold every recorded ball (missingBall)
// and, for the default keys, a shot.
FitResult fitStrike(const Setup& base, const Recording& recording, const std::vector<FitKey>& keys,
                    const FitOptions& options = {}, const std::function<void(const FitProgress&)>& progress = {},
                    std::stop_token stop = {});

// A local refit from `base`'s current values over the whole recording (one search with `local`, no
// windows, on the calling thread): what the calibration does for each recording at each trial of
// the shared keys.
// `strikeTime` is where the refit starts it (when fitted).
FitResult refitStrike(const Setup& base, const Recording& recording, const std::vector<FitKey>& keys,
                      double strikeTime, const FitOptions& options, const LocalOptions& local,
                      std::stop_token stop = {});

}  // namespace cuelab::fit
