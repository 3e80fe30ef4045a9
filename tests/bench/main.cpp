// cuelab-bench: prints one JSON object with the simulator's and the quartic solver's figures
// (issue 3): {"break": {...}, "quartic": {...}, "scaling": [...]}, and the engines of core/compare
// on the break at their default steps (issue 9): "compare": [{"engine": ..., "ms_median": ..., ...}].

#include "CompareBench.h"
#include "QuarticBench.h"
#include "SimulationBench.h"

#include <cstdio>

int main()
{
    using namespace cuelab::bench;
    const BreakFigures b = runBreakBench(200);
    const QuarticFigures q = runQuarticBench();
    const ScalingPoint s16 = runScalingBench(16);
    const ScalingPoint s64 = runScalingBench(64);
    const ScalingPoint s256 = runScalingBench(256);
    std::printf("{\"break\": {\"ms_median\": %.6g, \"ms_min\": %.6g, \"events\": %lld, \"runs\": %d}, "
                "\"quartic\": {\"ns_median\": %.6g, \"max_rel_error_random\": %.6g, \"max_rel_error_hard\": %.6g}, "
                "\"scaling\": [{\"balls\": %d, \"events_per_s\": %.6g}, {\"balls\": %d, \"events_per_s\": %.6g}, "
                "{\"balls\": %d, \"events_per_s\": %.6g}], \"compare\": %s}\n",
                b.msMedian, b.msMin, b.events, b.runs, q.nsMedian, q.maxRelErrorRandom, q.maxRelErrorHard,
                s16.balls, s16.eventsPerSecond, s64.balls, s64.eventsPerSecond, s256.balls, s256.eventsPerSecond,
                compareFiguresJson(runCompareBench(20)).c_str());
    return 0;
}
