#pragma once
// One derivative-free local search in a box: NLopt's Subplex (the default: Rowan's robust
// Nelder-Mead on subspaces), Nelder-Mead or BOBYQA. Deterministic: the same start gives the same
// evaluations in the same order, on any thread. NLopt itself stays behind this header.

#include <cstdint>
#include <functional>
#include <stop_token>
#include <vector>

namespace cuelab::fit {

enum class Method : std::uint8_t { Subplex, NelderMead, Bobyqa };

struct LocalOptions {
    Method method = Method::Subplex;
    int maxEvaluations = 400;
    double toleranceRel = 1e-4;  // of each key's first step: the search stops below this change
    double residualTolerance = 1e-6;  // m: ... or when the residual changes less than this
};

struct LocalResult {
    std::vector<double> x;
    double value = 0.0;
    int evaluations = 0;
    bool stopped = false;  // the stop token was requested
};

// Minimises f over [lower, upper] from `start` with first steps `step` (all of one size). f must be
// callable from the thread that calls localSearch; it is called once per evaluation.
LocalResult localSearch(const std::function<double(const std::vector<double>&)>& f, std::vector<double> start,
                        const std::vector<double>& lower, const std::vector<double>& upper,
                        const std::vector<double>& step, const LocalOptions& options, std::stop_token stop = {});

}  // namespace cuelab::fit
