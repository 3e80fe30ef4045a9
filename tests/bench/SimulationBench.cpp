#include "SimulationBench.h"

#include "Racks.h"
#include "Simulation.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <random>
#include <string>

namespace cuelab::bench {

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

Setup scalingSetup(int count, std::uint64_t seed)
{
    Setup s;
    s.table.kind = TableKind::Pool9ft;
    s.table.pockets = false;
    const double scale = std::sqrt(count / 16.0);
    s.table.length = 2.54 * scale;
    s.table.width = 1.27 * scale;
    s.simulation.maxTime = 600.0;
    const Table t = makeTable(s.table);
    const double R = t.ballRadius;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    while (static_cast<int>(s.balls.size()) < count) {
        const Vec2 p(R + (t.length - 2 * R) * u(rng), R + (t.width - 2 * R) * u(rng));
        bool free = true;
        for (const Ball& b : s.balls) free = free && (b.state.position - p).norm() >= 2 * R;
        if (!free) continue;
        Ball b;
        b.id = std::to_string(s.balls.size());
        b.radius = R;
        b.mass = t.ballMass;
        b.state.position = p;
        const double a = 2 * M_PI * u(rng), v = 0.5 + 2.5 * u(rng);
        b.state.velocity = Vec2(v * std::cos(a), v * std::sin(a));
        b.state.spin = Vec3(40 * (u(rng) - 0.5), 40 * (u(rng) - 0.5), 20 * (u(rng) - 0.5));
        b.state.motion = classify(b.state, R);
        s.balls.push_back(b);
    }
    return s;
}

}  // namespace

BreakFigures runBreakBench(int runs)
{
    // The cue ball leaves at 8 m/s: a centre hit gives it v = 2 V0 / (1 + m/M) (Alciatore TP A-30).
    const double cueBallSpeed = 8.0;                          // m/s
    const double massRatio = 0.170097 / CueStrike{}.cueMass;  // ball mass over cue mass, m / M
    const Setup setup = breakSetup(cueBallSpeed * (1.0 + massRatio) / 2.0);
    std::vector<double> ms;
    BreakFigures f;
    for (int k = 0; k < runs; ++k) {
        const Clock::time_point t0 = Clock::now();
        const SimulationResult r = simulate(setup);
        const Clock::time_point t1 = Clock::now();
        ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
        f.events = static_cast<long long>(r.events.size());
    }
    f.runs = runs;
    f.msMedian = median(ms);
    f.msMin = *std::min_element(ms.begin(), ms.end());
    return f;
}

ScalingPoint runScalingBench(int balls)
{
    // Processor time rather than wall time: the figure should not depend on what else the shared
    // machine runs. Several seeds, so that no single layout decides it.
    long long events = 0;
    double seconds = 0.0;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        const Setup setup = scalingSetup(balls, seed);
        const std::clock_t c0 = std::clock();
        const SimulationResult r = simulate(setup);
        const std::clock_t c1 = std::clock();
        events += static_cast<long long>(r.events.size());
        seconds += static_cast<double>(c1 - c0) / CLOCKS_PER_SEC;
    }
    return {balls, static_cast<double>(events) / seconds};
}

}  // namespace cuelab::bench
