#pragma once
// The odds of one shot under execution noise: the shot is struck again and again, each time with
// its strike parameters perturbed by normal errors (Noise.h), each run simulated and judged exactly
// as a sweep's shot (runShotWith), and the successes counted.
//
// Sample i of a run draws its errors from a generator seeded with (seed, i) alone, and batches of
// samples are added up in sample order, so the result is the same for any thread count. Samples
// with the same index use the same errors in every shot: two grid points of a sweep are compared
// with common random numbers, which keeps a map of odds smooth.

#include "Odds.h"
#include "Sweep.h"

#include <functional>
#include <stop_token>
#include <vector>

namespace cuelab::analysis {

// The nominal shot is spec.base with `values` of spec.variations applied (for a grid point; empty
// values with no variations: the base itself). Needs a shot (spec.base.shot) and uses spec.goal,
// spec.simulation and spec.setupName; spec.skip is ignored. Up to `threads` threads (0: all cores).
// `progress(done, total)` reports samples counted so far, from one thread at a time.
//
// Errors: the speed, side and height take value + sigma z; the heading takes value + the remainder
// of sigma z after whole turns (|error| <= 180°, the same aim as the whole error). The elevation is folded at 0
// (|value + sigma z|): a cue cannot point below the cloth, so a strike from a level cue scatters
// upwards only. A tip offset beyond the miscue limit (Map.h, 0.5 R) is a miscue, and a sample the
// errors make illegal (a speed below 0) is refused; both count as failures.
OddsResult shotOdds(const SweepSpec& spec, const std::vector<double>& values, const OddsRequest& request,
                    int threads, std::stop_token stop = {},
                    const std::function<void(long long done, long long total)>& progress = {});

// The strike values of sample `index`: the nominal values (heading, speed, side, height, elevation)
// plus the errors, with the elevation folded at 0.
std::array<double, kStrikeKeyCount> noisyStrike(const std::array<double, kStrikeKeyCount>& nominal,
                                                const NoiseModel& noise, std::uint64_t seed, long long index);

}  // namespace cuelab::analysis
