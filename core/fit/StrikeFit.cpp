#include "StrikeFit.h"

#include "LegalSetup.h"
#include "Parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>

namespace cuelab::fit {

namespace {

std::string struckId(const Setup& setup) { return setup.shot ? setup.shot->ball : std::string(); }

// A point of the search: the keys' values, then the strike time when it is fitted.
Setup withValues(const Setup& base, const std::vector<FitKey>& keys, const std::vector<double>& x)
{
    Setup s = base;
    for (std::size_t k = 0; k < keys.size(); ++k) keys[k].parameter.setNumber(s, x[k]);
    return s;
}

double strikeTimeOf(const std::vector<FitKey>& keys, const std::vector<double>& x)
{
    return x.size() > keys.size() ? x[keys.size()] : 0.0;
}

struct Bounds {
    std::vector<double> lower, upper, step;
};

Bounds boundsOf(const std::vector<FitKey>& keys, bool strikeTime)
{
    Bounds b;
    for (const FitKey& k : keys) {
        b.lower.push_back(k.lower);
        b.upper.push_back(k.upper);
        b.step.push_back(k.step);
    }
    if (strikeTime) {
        b.lower.push_back(-kStrikeTimeReach);
        b.upper.push_back(kStrikeTimeReach);
        b.step.push_back(0.005);  // s, a quarter of a frame at 50 Hz
    }
    return b;
}

// The windows of the schedule: those shorter than the recording, then the whole recording.
std::vector<double> windowsFor(const FitOptions& options, double duration)
{
    std::vector<double> w;
    for (double t : options.windows)
        if (t > 0.0 && t < duration && (w.empty() || t > w.back())) w.push_back(t);
    w.push_back(std::numeric_limits<double>::infinity());
    return w;
}

// The starts of the first stage: the base values first, then every combination of the heading
// offsets, speed factors and tip starts for those keys among `keys` (the others at their base values).
std::vector<std::vector<double>> startsFor(const Setup& base, const std::vector<FitKey>& keys,
                                           const FitOptions& options)
{
    std::vector<double> given;
    for (const FitKey& k : keys) given.push_back(k.parameter.number(base));
    if (options.fitStrikeTime) given.push_back(0.0);
    std::vector<std::vector<double>> starts{{}};
    for (const FitKey& k : keys) {
        const double x = k.parameter.number(base);
        std::vector<double> choices{x};
        if (isTipKey(k.parameter.key()) && !options.tipStarts.empty()) choices = options.tipStarts;
        if (k.parameter.key() == "shot.heading" && !options.headingStarts.empty()) {
            choices.clear();
            for (double d : options.headingStarts) choices.push_back(x + d);
        }
        if (k.parameter.key() == "shot.speed" && !options.speedStarts.empty()) {
            choices.clear();
            for (double f : options.speedStarts) choices.push_back(x * f);
        }
        std::vector<std::vector<double>> next;
        for (const std::vector<double>& s : starts)
            for (double c : choices) {
                next.push_back(s);
                next.back().push_back(std::clamp(c, k.lower, k.upper));
            }
        starts = std::move(next);
    }
    if (options.fitStrikeTime)
        for (std::vector<double>& s : starts) s.push_back(0.0);
    // The setup's own values first (a strike the caller knows, the last round's of a calibration).
    starts.erase(std::remove(starts.begin(), starts.end(), given), starts.end());
    starts.insert(starts.begin(), given);
    return starts;
}

struct Candidate {
    std::vector<double> x;
    double value = std::numeric_limits<double>::infinity();
    int evaluations = 0;
};

Measure measureOf(const FitOptions& options, double until, double strikeTime)
{
    return {options.balls, until, strikeTime, options.maxEvents};
}

void finish(FitResult& r, const Setup& base, const Recording& recording, const std::vector<FitKey>& keys,
            const std::vector<double>& x, const FitOptions& options)
{
    for (const FitKey& k : keys) r.keys.push_back(k.parameter.key());
    r.values.assign(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(keys.size()));
    r.strikeTime = strikeTimeOf(keys, x);
    r.setup = withValues(base, keys, x);
    const double all = std::numeric_limits<double>::infinity();
    Measure m = measureOf(options, all, r.strikeTime);
    r.rmse = residualOf(r.setup, recording, m, &r.residual);
    m.balls = BallSelection::Struck;
    r.rmseStruck = residualOf(r.setup, recording, m);
    m.balls = BallSelection::All;
    r.rmseAll = residualOf(r.setup, recording, m);
}

}  // namespace

double residualOf(const Setup& setup, const Recording& recording, const Measure& measure, Residual* out)
{
    if (firstSetupProblem(setup)) return kRefusedResidual;
    SimulationOptions so;
    so.maxEvents = measure.maxEvents;
    // Simulating past the window's end, or the recording's, is wasted.
    const double end = std::min(measure.until, recording.duration()) - measure.strikeTime;
    so.until = std::clamp(end, 0.0, setup.simulation.maxTime);
    const SimulationResult result = simulate(setup, so);
    if (result.status == SimulationStatus::EventLimit || result.status == SimulationStatus::Cancelled) return kRefusedResidual;
    ResidualOptions ro;
    ro.balls = measure.balls;
    ro.until = measure.until;
    ro.strikeTime = measure.strikeTime;
    ro.keepSamples = out != nullptr;
    Residual r = residual(result, recording, struckId(setup), ro);
    const double rmse = std::isfinite(r.rmse) ? r.rmse : kRefusedResidual;
    if (out) *out = std::move(r);
    return rmse;
}

FitResult fitStrike(const Setup& base, const Recording& recording, const std::vector<FitKey>& keys,
                    const FitOptions& options, const std::function<void(const FitProgress&)>& progress,
                    std::stop_token stop)
{
    const auto started = std::chrono::steady_clock::now();
    const Bounds bounds = boundsOf(keys, options.fitStrikeTime);
    const std::vector<double> windows = windowsFor(options, recording.duration());
    const auto residualAt = [&](const std::vector<double>& x, double until) {
        return residualOf(withValues(base, keys, x), recording, measureOf(options, until, strikeTimeOf(keys, x)));
    };

    std::vector<Candidate> seeds;
    for (std::vector<double>& x : startsFor(base, keys, options)) seeds.push_back({std::move(x)});

    FitProgress state;
    state.searchesTotal = static_cast<int>(seeds.size()) +
                          static_cast<int>(windows.size() - 1) * std::min(options.keep, static_cast<int>(seeds.size()));
    std::mutex progressMutex;
    long long evaluations = 0;
    bool cancelled = false;
    // The budget: every search at most its maximum, and the polish rounds. Evaluations are counted
    // as they happen, so the fraction moves while a search runs (progress is reported every 16).
    const double budget = double(state.searchesTotal) * std::max(1, options.local.maxEvaluations) +
                          double(std::max(0, options.polishRounds)) * std::max(1, options.polish.maxEvaluations);
    std::atomic<long long> spent{0};
    double credited = 0.0;  // unspent budget of finished searches (under progressMutex)
    const auto report = [&](bool force) {
        if (!progress) return;
        const long long n = ++spent;
        if (!force && n % 16 != 0) return;
        const std::lock_guard lock(progressMutex);
        state.fraction = std::clamp((double(spent.load()) + credited) / budget, state.fraction, 1.0);
        progress(state);
    };

    for (std::size_t w = 0; w < windows.size(); ++w) {
        const double window = windows[w];
        std::vector<Candidate> found(seeds.size());
        state.bestRmse = std::numeric_limits<double>::infinity();
        parallelFor(
            static_cast<int>(seeds.size()), options.threads,
            [&](int i) {
                const auto f = [&](const std::vector<double>& x) {
                    report(false);
                    return residualAt(x, window);
                };
                const LocalResult r = localSearch(f, seeds[static_cast<std::size_t>(i)].x, bounds.lower,
                                                  bounds.upper, bounds.step, options.local, stop);
                found[static_cast<std::size_t>(i)] = {r.x, r.value, r.evaluations};
                if (progress) {
                    const std::lock_guard lock(progressMutex);
                    ++state.searchesDone;
                    state.evaluations += r.evaluations;
                    state.bestRmse = std::min(state.bestRmse, r.value);
                    credited += std::max(0, options.local.maxEvaluations - r.evaluations);
                    state.fraction = std::clamp((double(spent.load()) + credited) / budget, state.fraction, 1.0);
                    progress(state);
                }
            },
            stop);
        for (const Candidate& c : found) evaluations += c.evaluations;
        // Searches a stop skipped keep their seed (never evaluated): they rank last.
        for (std::size_t i = 0; i < found.size(); ++i)
            if (found[i].x.empty()) found[i] = {seeds[i].x, std::numeric_limits<double>::infinity(), 0};
        // The results go on ranked by their residual over the next window: a strike that fits the
        // first half-second best need not fit the next seconds best (one evaluation each).
        if (w + 1 < windows.size() && !stop.stop_requested()) {
            parallelFor(static_cast<int>(found.size()), options.threads, [&](int i) {
                Candidate& c = found[static_cast<std::size_t>(i)];
                if (std::isfinite(c.value)) c.value = residualAt(c.x, windows[w + 1]);
            });
            evaluations += static_cast<long long>(found.size());
        }
        // The best by value, ties by start index (stable sort): independent of the thread count.
        std::vector<std::size_t> order(found.size());
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return found[a].value < found[b].value; });
        seeds.clear();
        for (std::size_t i = 0; i < order.size() && static_cast<int>(i) < std::max(1, options.keep); ++i)
            seeds.push_back(found[order[i]]);
        if (stop.stop_requested()) {
            cancelled = true;
            break;
        }
    }

    // The polish: near the best the event sequence is settled and the residual smooth, but its
    // valley is narrow (heading, speed and side trade against each other), where a simplex stalls.
    // Restarts with smaller first steps (the method of FitOptions::polish) walk it down.
    Candidate best = seeds.front();
    const double all = std::numeric_limits<double>::infinity();
    const auto full = [&](const std::vector<double>& x) {
        report(false);
        return residualAt(x, all);
    };
    std::vector<double> polishStep = bounds.step;
    for (int round = 0; !cancelled && round < options.polishRounds; ++round) {
        for (double& h : polishStep) h *= 0.1;
        const LocalResult r = localSearch(full, best.x, bounds.lower, bounds.upper, polishStep, options.polish, stop);
        evaluations += r.evaluations;
        cancelled = r.stopped;
        const bool better = r.value < best.value - options.polish.residualTolerance;
        if (r.value < best.value) best = {r.x, r.value, 0};
        {
            const std::lock_guard lock(progressMutex);
            credited += std::max(0, options.polish.maxEvaluations - r.evaluations);
        }
        if (!better) break;
    }
    if (progress && !cancelled) {
        const std::lock_guard lock(progressMutex);
        state.fraction = 1.0;
        progress(state);
    }

    FitResult result;
    finish(result, base, recording, keys, best.x, options);
    result.evaluations = evaluations;
    result.cancelled = cancelled;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

FitResult refitStrike(const Setup& base, const Recording& recording, const std::vector<FitKey>& keys,
                      double strikeTime, const FitOptions& options, const LocalOptions& local, std::stop_token stop)
{
    const auto started = std::chrono::steady_clock::now();
    const Bounds bounds = boundsOf(keys, options.fitStrikeTime);
    std::vector<double> start;
    for (const FitKey& k : keys) start.push_back(k.parameter.number(base));
    if (options.fitStrikeTime) start.push_back(strikeTime);
    const double all = std::numeric_limits<double>::infinity();
    const auto f = [&](const std::vector<double>& x) {
        return residualOf(withValues(base, keys, x), recording, measureOf(options, all, strikeTimeOf(keys, x)));
    };
    const LocalResult r = localSearch(f, start, bounds.lower, bounds.upper, bounds.step, local, stop);
    FitResult result;
    finish(result, base, recording, keys, r.x, options);
    result.evaluations = r.evaluations;
    result.cancelled = r.stopped;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

}  // namespace cuelab::fit
