// cuelab-setupbench: what validating a setup costs, the way the editor did it before (the whole
// setup written to JSON and parsed again, at every mouse move of a drag) and now (core/setup's
// validator on the values), and what the exact nearest legal spot costs for drops on a rack.
// Prints one JSON object; run it on an idle machine, the figures go to the notes.

#include "LegalPlacement.h"
#include "LegalSetup.h"
#include "Racks.h"
#include "SetupFile.h"

#include <QByteArray>
#include <QString>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

template <typename F>
double microsecondsPerCall(int calls, F&& f)
{
    std::vector<double> samples;
    for (int round = 0; round < 7; ++round) {
        const auto start = Clock::now();
        for (int i = 0; i < calls; ++i) f(i);
        samples.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count() / calls);
    }
    std::sort(samples.begin(), samples.end());
    return samples[samples.size() / 2];
}

}  // namespace

int main()
{
    using namespace cuelab;
    const Setup rack = breakSetup(5.0);  // 16 balls on a 9-ft table
    volatile bool sink = false;

    const double roundTrip = microsecondsPerCall(200, [&](int) {
        QString error;
        sink = io::parseSetup(io::serializeSetup(rack), QStringLiteral("bench.json"), &error).has_value();
    });
    const double validator = microsecondsPerCall(2000, [&](int) { sink = !firstSetupProblem(rack).has_value(); });
    const double oneBall = microsecondsPerCall(2000, [&](int) { sink = validateBall(rack, 0).empty(); });

    std::mt19937_64 rng(7);
    const Table table = makeTable(rack.table);
    std::uniform_real_distribution<double> ux(1.75, 2.2), uy(0.45, 0.82);
    std::vector<Vec2> drops(500);
    for (Vec2& p : drops) p = Vec2(ux(rng), uy(rng));
    const double nearest = microsecondsPerCall(500, [&](int i) {
        sink = nearestLegalSpot(rack, 0, drops[static_cast<std::size_t>(i) % drops.size()]).has_value();
    });
    (void)sink;
    std::printf("{\"balls\": %zu, \"json_round_trip_us\": %.3g, \"validator_us\": %.3g, \"validate_one_ball_us\": %.3g, "
                "\"nearest_legal_spot_on_rack_us\": %.3g}\n",
                rack.balls.size(), roundTrip, validator, oneBall, nearest);
    return 0;
}
