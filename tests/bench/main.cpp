// cuelab-bench: prints one JSON object with the simulator's and the quartic solver's figures
// (issue 3): {"break": {...}, "quartic": {...}, "scaling": [...]}, the engines of core/compare
// on the break at their default steps (issue 9): "compare": [{"engine": ..., "ms_median": ..., ...}],
// and the sweep engine's (issue 11): "sweep": {"map_100x100": [{"threads": 1, ...}, ...], "million": {...}},
// with the odds of one shot at 10^4 strikes (issue 25): "odds_10k": {...}.
//   cuelab-bench               everything but the 10^6-shot sweep
//   cuelab-bench --sweep       only the sweep figures, with the 10^6-shot sweep (about a minute)
//   cuelab-bench --cushions    the cost of one cushion hit per model, and of mathavan2010 per step count
//                              with its rebound error against 10^6 steps (issue 20)
//   cuelab-bench --soak N SEED [--jobs J] [--out DIR] [--no-determinism] [--class NAME] [--max-events N]
//                              [--first K] [--level]
//                              the random-shot soak's summary (issue 19, docs/soak.md); --level: the
//                              strike drops its vertical part (SimulationOptions::strikeKeepsElevation,
//                              on by default; --elevation, from before, is the default)
//   cuelab-bench --check [--level] [--trace] [--max-events N] [--set KEY=VALUE]... FILE...
//                              the soak's checks on setup files; exit 1 if any fails
//   cuelab-bench --cancel [--trials N] FILE...
//                              how fast a run answers its cancel token (issue 39), per file

#include "AnalysisBench.h"
#include "CancelBench.h"
#include "CompareBench.h"
#include "CushionBench.h"
#include "QuarticBench.h"
#include "SimulationBench.h"
#include "SoakBench.h"

#include <cstdio>
#include <algorithm>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

std::string sweepJson(bool million)
{
    using namespace cuelab::bench;
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<int> counts{1};
    for (int t = 2; t <= std::max(2, cores); ++t) counts.push_back(t);
    if (cores > 1) counts.push_back(2 * cores);  // oversubscribed: shows what hyperthreads or none add
    std::string out = "\"sweep\": {\"cores\": " + std::to_string(cores) + ", \"map_100x100\": [";
    const std::vector<SweepPoint> points = runMapBench(counts, 3);
    char buffer[256];
    for (std::size_t i = 0; i < points.size(); ++i) {
        const SweepPoint& p = points[i];
        std::snprintf(buffer, sizeof buffer, "%s{\"threads\": %d, \"shots\": %lld, \"seconds\": %.4g, "
                      "\"cpu_seconds\": %.4g, \"shots_per_s\": %.6g, \"speed_up\": %.3g}", i ? ", " : "", p.threads,
                      p.shots, p.seconds, p.cpuSeconds, p.shotsPerSecond, p.speedUp);
        out += buffer;
    }
    out += "]";
    const SweepPoint o = runOddsBench(3);
    std::snprintf(buffer, sizeof buffer, ", \"odds_10k\": {\"threads\": %d, \"strikes\": %lld, \"seconds\": %.4g, "
                  "\"cpu_seconds\": %.4g}", o.threads, o.shots, o.seconds, o.cpuSeconds);
    out += buffer;
    if (million) {
        const SweepPoint m = runMillionBench();
        std::snprintf(buffer, sizeof buffer, ", \"million\": {\"threads\": %d, \"shots\": %lld, \"seconds\": %.4g, "
                      "\"cpu_seconds\": %.4g, \"shots_per_s\": %.6g}", m.threads, m.shots, m.seconds, m.cpuSeconds,
                      m.shotsPerSecond);
        out += buffer;
    }
    return out + "}";
}

}  // namespace

int main(int argc, char** argv)
{
    using namespace cuelab::bench;
    if (argc > 1 && std::strcmp(argv[1], "--soak") == 0) return soakCommand(argc - 2, argv + 2);
    if (argc > 1 && std::strcmp(argv[1], "--check") == 0) return checkCommand(argc - 2, argv + 2);
    if (argc > 1 && std::strcmp(argv[1], "--cancel") == 0) return cancelCommand(argc - 2, argv + 2);
    if (argc > 1 && std::strcmp(argv[1], "--sweep") == 0) {
        std::printf("{%s}\n", sweepJson(true).c_str());
        return 0;
    }
    if (argc > 1 && std::strcmp(argv[1], "--cushions") == 0) {
        std::printf("{%s}\n", cushionJson(runCushionBench()).c_str());
        return 0;
    }
    const BreakFigures b = runBreakBench(200);
    const QuarticFigures q = runQuarticBench();
    const ScalingPoint s16 = runScalingBench(16);
    const ScalingPoint s64 = runScalingBench(64);
    const ScalingPoint s256 = runScalingBench(256);
    std::printf("{\"break\": {\"ms_median\": %.6g, \"ms_min\": %.6g, \"events\": %lld, \"runs\": %d}, "
                "\"quartic\": {\"ns_median\": %.6g, \"max_rel_error_random\": %.6g, \"max_rel_error_hard\": %.6g}, "
                "\"scaling\": [{\"balls\": %d, \"events_per_s\": %.6g}, {\"balls\": %d, \"events_per_s\": %.6g}, "
                "{\"balls\": %d, \"events_per_s\": %.6g}], \"compare\": %s, %s}\n",
                b.msMedian, b.msMin, b.events, b.runs, q.nsMedian, q.maxRelErrorRandom, q.maxRelErrorHard,
                s16.balls, s16.eventsPerSecond, s64.balls, s64.eventsPerSecond, s256.balls, s256.eventsPerSecond,
                compareFiguresJson(runCompareBench(20)).c_str(), sweepJson(false).c_str());
    return 0;
}
