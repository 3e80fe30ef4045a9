#pragma once
// The keys a fit varies (any numeric `--set` key, core/analysis Override.h), each with the box it
// stays in and the size of a first step. The box keeps a search among values the simulator takes
// and a player could play; the step is the scale on which the residual changes visibly.

#include "Override.h"

#include <string>
#include <variant>
#include <vector>

namespace cuelab::fit {

struct FitKey {
    analysis::Parameter parameter;
    double lower = 0.0;  // in the key's unit (degrees, m/s, radii, ...)
    double upper = 0.0;
    double step = 0.0;   // the search's first step
};

// The strike keys fitted when none are named (CONTRACT.md, `cuelab-cli fit`).
std::vector<std::string> defaultStrikeKeys();

// Resolves `keys` against `setup` (each must exist and be a number) and gives each its box around
// the setup's current value:
//   shot.heading   current +- 30 degrees, step 1 degree
//   shot.speed     [0.05, max(12, 3 x current)] m/s, step 5 % of current
//   shot.side|height  [-0.8, 0.8] radii (the miscue limit lies inside), step 0.1
//   shot.elevation [0, 60] degrees, step 2 degrees
//   *.restitution  [0.3, 1], step 0.03
//   any other key  [current / 5, 5 x current] (a positive value), [-1, 1] around 0, step 10 %.
std::variant<std::vector<FitKey>, analysis::OverrideError> resolveFitKeys(const Setup& setup,
                                                                          const std::vector<std::string>& keys);

// Whether a key is one of the tip offsets (fitted from several starts).
bool isTipKey(const std::string& key);

}  // namespace cuelab::fit
