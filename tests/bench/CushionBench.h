#pragma once
// The cost of one ball-cushion hit per model, and of Mathavan 2010 against its step count (its
// `steps`, legal from 10 to 10^6): processor time per hit and the rebound's distance from the
// 10^6-step one, so that docs/cushion-models.md and the Physics panel's tooltip can say what a step
// count costs and buys.

#include <string>
#include <vector>

namespace cuelab::bench {

struct CushionCost {
    std::string model;        // "han2005", "mathavan2010", ...
    double steps = 0.0;       // mathavan2010's steps; 0 for the others
    double usPerHit = 0.0;    // microseconds of processor time per resolved hit, median of the repeats
    double velocityError = 0.0;  // m/s, |v' - v'(10^6 steps)| (mathavan2010 only; 0 otherwise)
};

std::vector<CushionCost> runCushionBench();
std::string cushionJson(const std::vector<CushionCost>& costs);

}  // namespace cuelab::bench
