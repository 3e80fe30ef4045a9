#include "LocalSearch.h"

#include <nlopt.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cuelab::fit {

namespace {

struct Context {
    const std::function<double(const std::vector<double>&)>* f;
    std::stop_token stop;
    nlopt_opt opt = nullptr;
    std::vector<double> x;
    std::vector<double> bestX;
    double best = std::numeric_limits<double>::infinity();
    int evaluations = 0;
    bool stopped = false;
};

double objective(unsigned n, const double* x, double* /*gradient*/, void* data)
{
    auto* c = static_cast<Context*>(data);
    if (c->stop.stop_requested()) {
        c->stopped = true;
        nlopt_force_stop(c->opt);
        return c->best;
    }
    c->x.assign(x, x + n);
    double value = (*c->f)(c->x);
    // A value that is not a number (it should not happen) must not steer the search.
    if (!std::isfinite(value)) value = std::numeric_limits<double>::max();
    ++c->evaluations;
    // The best point is kept here, not taken from NLopt, so that a forced stop keeps it too.
    if (value < c->best) {
        c->best = value;
        c->bestX = c->x;
    }
    return value;
}

nlopt_algorithm algorithm(Method m)
{
    switch (m) {
    case Method::NelderMead: return NLOPT_LN_NELDERMEAD;
    case Method::Bobyqa: return NLOPT_LN_BOBYQA;
    case Method::Subplex: break;
    }
    return NLOPT_LN_SBPLX;
}

}  // namespace

LocalResult localSearch(const std::function<double(const std::vector<double>&)>& f, std::vector<double> start,
                        const std::vector<double>& lower, const std::vector<double>& upper,
                        const std::vector<double>& step, const LocalOptions& options, std::stop_token stop)
{
    const auto n = static_cast<unsigned>(start.size());
    for (std::size_t i = 0; i < start.size(); ++i) start[i] = std::clamp(start[i], lower[i], upper[i]);
    Context c{&f, stop};
    c.bestX = start;
    if (n == 0) {
        c.best = f(start);
        return {start, c.best, 1, false};
    }
    c.opt = nlopt_create(algorithm(options.method), n);
    nlopt_set_min_objective(c.opt, objective, &c);
    nlopt_set_lower_bounds(c.opt, lower.data());
    nlopt_set_upper_bounds(c.opt, upper.data());
    nlopt_set_initial_step(c.opt, step.data());
    std::vector<double> xtol(step);
    for (double& t : xtol) t *= options.toleranceRel;
    nlopt_set_xtol_abs(c.opt, xtol.data());
    nlopt_set_ftol_abs(c.opt, options.residualTolerance);
    nlopt_set_maxeval(c.opt, options.maxEvaluations);
    std::vector<double> x = start;
    double value = 0.0;
    nlopt_optimize(c.opt, x.data(), &value);  // any outcome (a roundoff stop, a forced stop) keeps c.best
    nlopt_destroy(c.opt);
    if (c.evaluations == 0) {
        c.best = f(start);
        c.evaluations = 1;
    }
    return {c.bestX, c.best, c.evaluations, c.stopped};
}

}  // namespace cuelab::fit
