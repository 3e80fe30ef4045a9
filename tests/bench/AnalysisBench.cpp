#include "AnalysisBench.h"

#include "Map.h"
#include "ShotOdds.h"
#include "Sweep.h"

#include <chrono>
#include <ctime>
#include <stdexcept>

namespace cuelab::bench {

namespace {

using Clock = std::chrono::steady_clock;
using namespace cuelab::analysis;

// resources/examples/half-ball-cut.json, built in code (the bench links no Qt).
Setup halfBallCut()
{
    Setup s;
    s.name = "Half-ball cut";
    Ball cue;
    cue.id = "cue";
    cue.state.position = Vec2(1.2, 0.891425);
    Ball one;
    one.id = "1";
    one.state.position = Vec2(1.9338, 0.92);
    s.balls = {cue, one};
    CueStrike shot;
    shot.ball = "cue";
    shot.speed = 2.0;
    shot.height = 0.4;
    s.shot = shot;
    return s;
}

Variation vary(const Setup& s, const char* text)
{
    auto v = parseVariation(s, text);
    if (auto* e = std::get_if<OverrideError>(&v)) throw std::runtime_error(e->message);
    return std::get<Variation>(v);
}

SweepSpec cutSpec()
{
    SweepSpec spec;
    spec.base = halfBallCut();
    std::string error;
    auto goal = std::get<Goal>(parseGoal("pot:1@pocket-tr,no-scratch"));
    spec.goal = *ResolvedGoal::resolve(goal, spec.base, &error);
    return spec;
}

SweepPoint timeSweep(const SweepSpec& spec, int runs)
{
    SweepPoint point;
    point.threads = threadCount(spec);
    point.shots = shotCount(spec);
    point.seconds = 1e300;
    for (int r = 0; r < runs; ++r) {
        long long met = 0;
        const auto start = Clock::now();
        const std::clock_t cpuStart = std::clock();
        runSweep(spec, [&](ShotResult& s) { met += s.goalMet ? 1 : 0; });
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        if (seconds < point.seconds) {
            point.seconds = seconds;
            point.cpuSeconds = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
        }
        if (met == 0) throw std::runtime_error("no shot of the bench met its goal");
    }
    point.shotsPerSecond = static_cast<double>(point.shots) / point.seconds;
    return point;
}

}  // namespace

std::vector<SweepPoint> runMapBench(const std::vector<int>& threadCounts, int runs)
{
    SweepSpec spec = cutSpec();
    spec.variations = {vary(spec.base, "shot.height=-0.5:0.5:100"), vary(spec.base, "shot.side=-0.5:0.5:100")};
    std::vector<SweepPoint> points;
    for (int threads : threadCounts) {
        spec.threads = threads;
        points.push_back(timeSweep(spec, runs));
        points.back().speedUp = points.front().seconds / points.back().seconds;
    }
    return points;
}

SweepPoint runMillionBench()
{
    SweepSpec spec = cutSpec();
    spec.variations = {vary(spec.base, "shot.heading=-3:3:100"), vary(spec.base, "shot.speed=1:3:100"),
                       vary(spec.base, "shot.side=-0.4:0.4:100")};
    return timeSweep(spec, 1);
}

SweepPoint runOddsBench(int runs)
{
    const SweepSpec spec = cutSpec();
    OddsRequest request;
    request.noise = *presetNoise("fastfiz", 0.028575);
    request.samples = 10000;
    SweepPoint point;
    point.threads = threadCount(spec);
    point.shots = request.samples;
    point.seconds = 1e300;
    for (int r = 0; r < runs; ++r) {
        const auto start = Clock::now();
        const std::clock_t cpuStart = std::clock();
        const OddsResult odds = shotOdds(spec, {}, request, 0);
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        if (odds.successes == 0) throw std::runtime_error("the odds bench's shot never met its goal");
        if (seconds < point.seconds) {
            point.seconds = seconds;
            point.cpuSeconds = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
        }
    }
    point.shotsPerSecond = static_cast<double>(point.shots) / point.seconds;
    return point;
}

}  // namespace cuelab::bench
