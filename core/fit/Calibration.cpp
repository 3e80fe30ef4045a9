#include "Calibration.h"

#include "Parallel.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>

namespace cuelab::fit {

namespace {

void setShared(Setup& setup, const std::vector<FitKey>& shared, const std::vector<double>& values)
{
    for (std::size_t k = 0; k < shared.size(); ++k) shared[k].parameter.setNumber(setup, values[k]);
}

// The strike keys of one recording's setup (their boxes around its current strike).
std::vector<FitKey> strikeKeysOf(const Setup& setup, const std::vector<std::string>& keys)
{
    auto resolved = resolveFitKeys(setup, keys);
    if (auto* error = std::get_if<analysis::OverrideError>(&resolved)) throw std::invalid_argument(error->message);
    return std::get<std::vector<FitKey>>(std::move(resolved));
}

double meanOf(const std::vector<FitResult>& fits)
{
    double sum = 0.0;
    for (const FitResult& f : fits) sum += f.rmse;
    return fits.empty() ? 0.0 : sum / static_cast<double>(fits.size());
}

}  // namespace

CalibrationResult calibrate(const std::vector<CalibrationProblem>& problems, const std::vector<FitKey>& sharedKeys,
                            const std::vector<std::string>& strikeKeys, const CalibrationOptions& options,
                            const std::function<void(const CalibrationProgress&)>& progress, std::stop_token stop)
{
    const auto started = std::chrono::steady_clock::now();
    CalibrationResult out;
    for (const FitKey& k : sharedKeys) out.sharedKeys.push_back(k.parameter.key());
    if (problems.empty()) return out;
    const int n = static_cast<int>(problems.size());

    std::vector<double> shared;
    for (const FitKey& k : sharedKeys) shared.push_back(k.parameter.number(problems.front().setup));
    std::vector<double> lower, upper, step;
    for (const FitKey& k : sharedKeys) {
        lower.push_back(k.lower);
        upper.push_back(k.upper);
        step.push_back(k.step);
    }
    // Each recording's setup: its strike (updated every round), the shared keys set per trial.
    std::vector<Setup> setups;
    for (const CalibrationProblem& p : problems) {
        setups.push_back(p.setup);
        setShared(setups.back(), sharedKeys, shared);
    }

    FitOptions strikeOptions = options.strike;
    strikeOptions.threads = 1;  // the recordings run in parallel instead
    std::atomic<long long> evaluations{0};
    std::mutex progressMutex;
    CalibrationProgress state;
    state.recordings = n;
    const auto report = [&] {
        if (!progress) return;
        progress(state);
    };

    std::vector<FitResult> fits(static_cast<std::size_t>(n));
    double best = std::numeric_limits<double>::infinity();
    for (int round = 1; round <= std::max(1, options.rounds) && !stop.stop_requested(); ++round) {
        state.round = round;
        state.recordingsDone = 0;
        // Every recording's strike at the current shared values, the whole schedule.
        parallelFor(
            n, options.threads,
            [&](int i) {
                const auto u = static_cast<std::size_t>(i);
                FitResult f = fitStrike(setups[u], problems[u].recording, strikeKeysOf(setups[u], strikeKeys),
                                        strikeOptions, {}, stop);
                evaluations += f.evaluations;
                fits[u] = std::move(f);
                const std::lock_guard lock(progressMutex);
                ++state.recordingsDone;
                report();
            },
            stop);
        if (stop.stop_requested()) break;
        for (int i = 0; i < n; ++i) setups[static_cast<std::size_t>(i)] = fits[static_cast<std::size_t>(i)].setup;
        const double roundStart = meanOf(fits);
        if (round == 1) best = roundStart;
        state.meanRmse = std::min(best, roundStart);

        // The outer search over the shared keys; each trial refits every strike from this round's.
        std::vector<std::vector<FitKey>> keysOf;
        for (const Setup& s : setups) keysOf.push_back(strikeKeysOf(s, strikeKeys));
        const auto trial = [&](const std::vector<double>& values, std::vector<FitResult>* keep) {
            std::vector<FitResult> refits(static_cast<std::size_t>(n));
            parallelFor(
                n, options.threads,
                [&](int i) {
                    const auto u = static_cast<std::size_t>(i);
                    Setup s = setups[u];
                    setShared(s, sharedKeys, values);
                    refits[u] = refitStrike(s, problems[u].recording, keysOf[u], fits[u].strikeTime, strikeOptions,
                                            options.inner, stop);
                    evaluations += refits[u].evaluations;
                },
                stop);
            const double mean = meanOf(refits);
            if (keep) *keep = std::move(refits);
            return mean;
        };
        const auto objective = [&](const std::vector<double>& values) {
            const double mean = trial(values, nullptr);
            const std::lock_guard lock(progressMutex);
            ++state.outerEvaluations;
            state.meanRmse = std::min(state.meanRmse, mean);
            report();
            return mean;
        };
        const LocalResult r = localSearch(objective, shared, lower, upper, step, options.outer, stop);
        if (stop.stop_requested()) break;
        std::vector<FitResult> refits;
        const double mean = trial(r.x, &refits);
        if (mean < roundStart) {
            shared = r.x;
            fits = std::move(refits);
            for (int i = 0; i < n; ++i) setups[static_cast<std::size_t>(i)] = fits[static_cast<std::size_t>(i)].setup;
        }
        const double previous = best;
        best = std::min(best, std::min(mean, roundStart));
        if (round > 1 && previous - best < 0.01 * previous) break;
    }

    out.shared = shared;
    out.fits = std::move(fits);
    out.meanRmse = meanOf(out.fits);
    out.evaluations = evaluations;
    out.cancelled = stop.stop_requested();
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return out;
}

}  // namespace cuelab::fit
