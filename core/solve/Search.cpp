#include "Search.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace cuelab::solve {

namespace {

// Initial and smallest steps per strike key (heading °, speed m/s, side R, height R, elevation °):
// the first steps span a fair share of what the noise presets scatter; the smallest are finer than
// any window a player could hold.
constexpr Strike kInitialStep = {0.5, 0.4, 0.15, 0.15, 5.0};
constexpr Strike kSmallestStep = {0.004, 0.004, 0.004, 0.004, 0.1};
// The smoothing stage's noise is at least this (for a key asked to be struck exactly, so that the
// first stage still has a slope).
constexpr Strike kSmoothingFloor = {0.1, 0.05, 0.02, 0.02, 0.5};

}  // namespace

Strike clampToBounds(Strike s, const StrikeBounds& b)
{
    s[1] = std::clamp(s[1], b.minSpeed, b.maxSpeed);
    const double tip = std::hypot(s[2], s[3]);
    if (tip > b.maxTipOffset) {
        s[2] *= b.maxTipOffset / tip;
        s[3] *= b.maxTipOffset / tip;
    }
    s[4] = std::clamp(s[4], 0.0, b.maxElevation);
    return s;
}

Refined refine(Evaluator& evaluator, const Strike& start, const SolveRequest& request, std::uint64_t crnSeed,
               const std::function<void()>& onStep)
{
    std::vector<std::size_t> dims;
    for (StrikeKey k : request.vary) dims.push_back(static_cast<std::size_t>(k));

    Refined r;
    r.strike = clampToBounds(start, request.bounds);
    // The stages: (noise factor, steps as a share of the first ones, draws as a multiple of
    // searchSamples, iterations as a share of maxIterations).
    struct Stage {
        double noise, step;
        int draws;
        double iterations;
    };
    constexpr std::array<Stage, 3> stages = {Stage{2.0, 1.0, 1, 1.0}, Stage{1.0, 0.25, 1, 1.0}, Stage{1.0, 1.0 / 16.0, 4, 0.5}};
    Strike step{};
    for (const Stage& stage : stages) {
        analysis::NoiseModel noise = request.noise;
        for (std::size_t k = 0; k < noise.sigma.size(); ++k)
            noise.sigma[k] = std::max(stage.noise * noise.sigma[k], stage.noise > 1.0 ? kSmoothingFloor[k] : 0.0);
        for (std::size_t k = 0; k < step.size(); ++k) step[k] = stage.step * kInitialStep[k];
        const int draws = stage.draws * request.searchSamples;
        const int iterations = static_cast<int>(std::ceil(stage.iterations * request.maxIterations));
        Score current = evaluator.score({r.strike}, noise, crnSeed, draws).front();
        for (int it = 0; it < iterations && !evaluator.stopped(); ++it) {
            bool coarse = false;
            for (std::size_t k : dims) coarse = coarse || step[k] >= kSmallestStep[k];
            if (!coarse) break;
            std::vector<Strike> neighbours;
            for (std::size_t k : dims)
                for (double sign : {1.0, -1.0}) {
                    Strike n = r.strike;
                    n[k] += sign * step[k];
                    n = clampToBounds(n, request.bounds);
                    if (n != r.strike) neighbours.push_back(n);
                }
            const std::vector<Score> scores = evaluator.score(neighbours, noise, crnSeed, draws);
            ++r.iterations;
            if (onStep) onStep();
            std::size_t best = scores.size();
            for (std::size_t i = 0; i < scores.size(); ++i)
                if (better(scores[i], best < scores.size() ? scores[best] : current)) best = i;
            if (best < scores.size()) {
                r.strike = neighbours[best];
                current = scores[best];
            } else {
                for (std::size_t k : dims) step[k] /= 2.0;
            }
        }
        r.score = current;
    }
    return r;
}

}  // namespace cuelab::solve
