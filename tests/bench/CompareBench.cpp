#include "CompareBench.h"

#include "Divergence.h"
#include "Racks.h"

#include <algorithm>
#include <cstdio>
#include <ctime>

namespace cuelab::bench {

std::vector<EngineFigures> runCompareBench(int runs)
{
    using namespace cuelab::compare;
    const double massRatio = 0.170097 / CueStrike{}.cueMass;
    const Setup setup = breakSetup(8.0 * (1.0 + massRatio) / 2.0);  // as runBreakBench
    std::vector<EngineFigures> out;
    for (EngineKind kind : {EngineKind::Exact, EngineKind::Discrete, EngineKind::Box2D}) {
        EngineSettings s;
        s.engine = kind;
        const EngineSettings r = resolved(s);
        std::vector<double> ms;
        for (int k = 0; k < runs; ++k) {
            const std::clock_t c0 = std::clock();
            const EngineRun run = runEngine(setup, s);
            ms.push_back(1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
        }
        std::sort(ms.begin(), ms.end());
        const Comparison c = compareEngines(setup, s);
        EngineFigures f;
        f.engine = std::string(toString(kind));
        f.dt = r.dt;
        f.substeps = r.substeps;
        f.runs = runs;
        f.msMedian = ms[ms.size() / 2];
        f.maxPositionError = c.divergence.maxError;
        for (double e : c.divergence.finalError) f.finalPositionError = std::max(f.finalPositionError, e);
        f.firstSequenceDifference = c.divergence.firstSequenceDifference.value_or(-1);
        f.worstOverlap = c.divergence.worstOverlap;
        f.collisions = static_cast<int>(c.run.collisions.size());
        out.push_back(f);
    }
    return out;
}

std::string compareFiguresJson(const std::vector<EngineFigures>& figures)
{
    std::string text = "[";
    for (std::size_t i = 0; i < figures.size(); ++i) {
        const EngineFigures& f = figures[i];
        char line[512];
        std::snprintf(line, sizeof line,
                      "%s{\"engine\": \"%s\", \"dt\": %.6g, \"substeps\": %d, \"ms_median\": %.4g, \"runs\": %d, "
                      "\"max_position_error\": %.4g, \"final_position_error\": %.4g, \"first_sequence_difference\": %d, "
                      "\"worst_overlap\": %.4g, \"collisions\": %d}",
                      i ? ", " : "", f.engine.c_str(), f.dt, f.substeps, f.msMedian, f.runs, f.maxPositionError,
                      f.finalPositionError, f.firstSequenceDifference, f.worstOverlap, f.collisions);
        text += line;
    }
    return text + "]";
}

}  // namespace cuelab::bench
