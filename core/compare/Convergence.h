#pragma once
// Convergence of a stepped engine towards the exact run as its step shrinks (issue 9).

#include "Divergence.h"
#include "Engine.h"

#include <optional>
#include <vector>

namespace cuelab::compare {

struct ConvergencePoint {
    double dt = 0.0;              // s
    double maxError = 0.0;        // m, Divergence::maxError
    double finalError = 0.0;      // m, the largest final error over the balls
    double worstOverlap = 0.0;    // m
    std::optional<int> firstSequenceDifference;
};

// `base`'s engine at each step of `steps` (its other settings kept), against one exact run.
std::vector<ConvergencePoint> convergenceStudy(const Setup& setup, const EngineSettings& base,
                                               const std::vector<double>& steps);

// The order p of error ~ C dt^p: the least-squares slope of log(error) against log(dt) over the
// points with error > 0 (nullopt with fewer than two such points).
std::optional<double> convergenceOrder(const std::vector<double>& steps, const std::vector<double>& errors);

// `count` steps spaced evenly in log from `largest` down to `smallest`.
std::vector<double> logSpacedSteps(double largest, double smallest, int count);

}  // namespace cuelab::compare
