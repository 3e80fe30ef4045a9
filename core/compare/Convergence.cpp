#include "Convergence.h"

#include <algorithm>
#include <cmath>

namespace cuelab::compare {

std::vector<ConvergencePoint> convergenceStudy(const Setup& setup, const EngineSettings& base,
                                               const std::vector<double>& steps)
{
    std::vector<ConvergencePoint> out;
    for (double dt : steps) {
        EngineSettings s = base;
        s.dt = dt;
        const Comparison c = compareEngines(setup, s);  // the exact run sampled on this engine's steps
        const Divergence& d = c.divergence;
        ConvergencePoint p;
        p.dt = dt;
        p.maxError = d.maxError;
        for (double e : d.finalError) p.finalError = std::max(p.finalError, e);
        p.worstOverlap = d.worstOverlap;
        p.firstSequenceDifference = d.firstSequenceDifference;
        out.push_back(p);
    }
    return out;
}

std::optional<double> convergenceOrder(const std::vector<double>& steps, const std::vector<double>& errors)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (std::size_t i = 0; i < std::min(steps.size(), errors.size()); ++i) {
        if (!(errors[i] > 0.0) || !(steps[i] > 0.0)) continue;
        const double x = std::log(steps[i]), y = std::log(errors[i]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        ++n;
    }
    const double denominator = n * sxx - sx * sx;
    if (n < 2 || denominator <= 0.0) return std::nullopt;
    return (n * sxy - sx * sy) / denominator;
}

std::vector<double> logSpacedSteps(double largest, double smallest, int count)
{
    std::vector<double> out;
    if (count <= 1) return {largest};
    for (int i = 0; i < count; ++i)
        out.push_back(largest * std::pow(smallest / largest, static_cast<double>(i) / (count - 1)));
    return out;
}

}  // namespace cuelab::compare
