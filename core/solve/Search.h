#pragma once
// The refinement of one seed: a compass search (Kolda, Lewis and Torczon, "Optimization by direct
// search", SIAM Review 2003) over the varied strike keys. Each step scores the 2n neighbours
// x ± step_k e_k together (one parallel batch) on the same noise draws as the current point; the
// best neighbour that beats the current point becomes the current point, and when none does every
// step is halved. It needs no derivatives, which the count of successes does not have, and with
// common random numbers a comparison of two candidates is not blurred by their draws differing.
//
// Three stages: first the noise doubled (the probability under a wider scatter is a smoothed version
// of the true one: it still slopes where the true one is flat at 0 or 1), then the true noise from
// a quarter of the first steps, then a polish from a sixteenth of them on four times the draws
// (a success rate of 0.1 is told from 0.15 only on many draws).

#include "Objective.h"

#include <cstdint>
#include <functional>

namespace cuelab::solve {

struct Refined {
    Strike strike{};
    Score score;  // under the true noise, on the refinement's draws
    int iterations = 0;
};

// Keeps a strike inside the bounds: the speed and elevation clamped, the tip pulled in radially.
Strike clampToBounds(Strike strike, const StrikeBounds& bounds);

Refined refine(Evaluator& evaluator, const Strike& start, const SolveRequest& request, std::uint64_t crnSeed,
               const std::function<void()>& onStep = {});

}  // namespace cuelab::solve
