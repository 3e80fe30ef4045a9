#pragma once
// Success odds under execution noise (CONTRACT.md, version 2, "odds"): what is asked (the noise, how
// many samples at most, the seed, when to stop early) and what comes back (successes of samples,
// with the Wilson 95 % interval). The computation is in ShotOdds.h.

#include "Noise.h"

#include <cstdint>

namespace cuelab::analysis {

struct OddsRequest {
    NoiseModel noise;
    long long samples = 10000;  // at most this many
    std::uint64_t seed = 0;
    // Stop once the Wilson interval's half-width is at most this (0: never stop early). Checked only
    // after every `batch` samples, in sample order, so the stopping point is a function of the seed
    // and the shot alone, never of the thread count or the timing.
    double halfWidth = 0.0;
    int batch = 250;
};

struct Interval {
    double low = 0.0, high = 1.0;
    double halfWidth() const { return (high - low) / 2.0; }
};

// The Wilson score interval (Wilson 1927) at 95 % (z = 1.959963984540054, the normal's 97.5 %
// quantile) for `successes` of `n`: centre (p + z²/2n) / (1 + z²/n), half-width
// z / (1 + z²/n) * sqrt(p (1 - p) / n + z² / 4n²) with p = successes / n. [0, 1] for n = 0.
Interval wilson95(long long successes, long long n);

struct OddsResult {
    long long samples = 0;     // samples counted (fewer than asked after an early stop or a cancel)
    long long successes = 0;   // samples that met the goal
    long long miscues = 0;     // samples whose tip offset lay beyond the miscue limit (failures)
    long long refused = 0;     // samples the errors made illegal (a negative speed; failures)
    long long unfinished = 0;  // samples cut short by the event cap or max_time (failures)
    bool stoppedEarly = false;
    bool cancelled = false;

    double probability() const { return samples > 0 ? static_cast<double>(successes) / static_cast<double>(samples) : 0.0; }
    Interval ci95() const { return wilson95(successes, samples); }
};

}  // namespace cuelab::analysis
