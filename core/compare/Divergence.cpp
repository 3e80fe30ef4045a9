#include "Divergence.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cuelab::compare {

bool sameCollision(const Collision& a, const Collision& b)
{
    return a.kind == b.kind && a.ball == b.ball && a.other == b.other && a.agent == b.agent;
}

Divergence measureDivergence(const EngineRun& exact, const EngineRun& run)
{
    if (exact.ids != run.ids) throw std::invalid_argument("measureDivergence: the runs have different balls");
    if (exact.sampleDt != run.sampleDt) throw std::invalid_argument("measureDivergence: different sample steps");
    Divergence d;
    const std::size_t balls = exact.ids.size();
    // A run that ended at rest keeps its last state for ever; one stopped by the time limit with
    // balls moving says nothing past its end, so the comparison stops there.
    std::size_t count = std::max(exact.samples.size(), run.samples.size());
    if (!exact.atRest) count = std::min(count, exact.samples.size());
    if (!run.atRest) count = std::min(count, run.samples.size());
    d.error.assign(balls, std::vector<double>(count, 0.0));
    d.times.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        d.times[k] = exact.sampleTime(k);
        const std::vector<BallSample>& a = exact.samples[std::min(k, exact.samples.size() - 1)];
        const std::vector<BallSample>& b = run.samples[std::min(k, run.samples.size() - 1)];
        for (std::size_t i = 0; i < balls; ++i) {
            const double e = (b[i].position - a[i].position).norm();
            d.error[i][k] = e;
            if (e > d.maxError) {
                d.maxError = e;
                d.maxErrorBall = static_cast<int>(i);
                d.maxErrorTime = d.times[k];
            }
        }
    }
    for (std::size_t i = 0; i < balls; ++i) d.finalError.push_back(count ? d.error[i].back() : 0.0);

    const std::size_t common = std::min(exact.collisions.size(), run.collisions.size());
    std::size_t k = 0;
    for (; k < common && sameCollision(exact.collisions[k], run.collisions[k]); ++k) {
        EventTimeDifference m{static_cast<int>(k), exact.collisions[k].time, run.collisions[k].time};
        d.maxEventTimeDifference = std::max(d.maxEventTimeDifference, std::abs(m.difference()));
        d.matched.push_back(m);
    }
    if (k < exact.collisions.size() || k < run.collisions.size()) d.firstSequenceDifference = static_cast<int>(k);
    d.worstOverlap = run.worstOverlap;
    return d;
}

EngineRun exactRunFor(const Setup& setup, const EngineSettings& settings, const Progress& progress)
{
    EngineSettings exact;
    exact.engine = EngineKind::Exact;
    exact.sampleDt = resolved(settings).sampleDt;
    return runEngine(setup, exact, progress);
}

Comparison compareWith(const Setup& setup, const EngineSettings& settings, EngineRun exact, const Progress& progress)
{
    Comparison c;
    c.exact = std::move(exact);
    c.run = settings.engine == EngineKind::Exact ? c.exact : runEngine(setup, settings, progress);
    if (c.run.cancelled || c.exact.samples.empty() || c.run.samples.empty()) return c;
    c.divergence = measureDivergence(c.exact, c.run);
    return c;
}

Comparison compareEngines(const Setup& setup, const EngineSettings& settings, const Progress& progress)
{
    return compareWith(setup, settings, exactRunFor(setup, settings), progress);
}

}  // namespace cuelab::compare
