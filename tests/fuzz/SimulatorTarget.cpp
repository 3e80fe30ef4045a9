#include "FuzzTargets.h"

#include "Motion.h"
#include "SetupFile.h"
#include "Simulation.h"
#include "SimulationChecks.h"

#include <QByteArray>
#include <QString>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cuelab::fuzz {

namespace {

// Bounds that keep one input fast enough for a fuzzer (thousands of runs per second), not limits of
// the simulator: larger setups are skipped, long runs capped.
constexpr std::size_t kMaxBalls = 24;
constexpr long long kMaxEvents = 20000;


}  // namespace

int fuzzSimulator(const std::uint8_t* data, std::size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const std::optional<Setup> setup = io::parseSetup(bytes, QStringLiteral("fuzz.json"), nullptr);
    if (!setup || setup->balls.size() > kMaxBalls) return 0;
    SimulationOptions options;
    options.maxEvents = kMaxEvents;
    options.until = std::min(setup->simulation.maxTime, 120.0);
    const SimulationResult r = simulate(*setup, options);

    // It ends, and says how.
    check(r.status != SimulationStatus::EventLimit || !r.error.empty(), "an event limit without a message");
    check(std::isfinite(r.endTime) && r.endTime >= 0.0, "end time", r.endTime);
    if (r.status == SimulationStatus::AllAtRest) {
        for (std::size_t i = 0; i < r.balls.size(); ++i) {
            const MotionState m = r.stateAt(static_cast<int>(i), r.endTime).motion;
            check(m == MotionState::Stationary || isOutOfPlay(m), "a ball still moves at rest", double(i));  // (or off the table)
        }
    }
    // At every event: no overlap, every ball on the table or pocketed, no energy rise after the strike.
    double last = -1.0;
    double energy = 0.0;
    for (std::size_t k = 0; k < r.events.size(); ++k) {
        const Event& e = r.events[k];
        check(std::isfinite(e.time) && e.time >= last, "events out of time order", e.time);
        last = e.time;
        const std::vector<BallState> states = r.statesAt(e.time);
        check(testing::maxOverlap(r, states) <= 1e-9, "overlap at an event", testing::maxOverlap(r, states));
        for (std::size_t i = 0; i < states.size(); ++i) {
            check(states[i].position.allFinite() && states[i].velocity.allFinite() && states[i].spin.allFinite(),
                  "a non-finite state", double(i));
            check(testing::onTable(r, states[i], r.balls[i].radius), "a ball off the table", double(i));
        }
        const double now = testing::totalEnergy(r, states);
        if (e.kind != EventKind::CueStrike && k > 0) {
            // No event adds energy (a push is a held contact, Contact.h): rounding only.
            const double allowance = 0.0;
            if (!(now <= energy * (1.0 + 1e-12) + allowance + 1e-15))
                std::fprintf(stderr, "event %zu (%s) at t = %.17g: %.17g J -> %.17g J\n", k,
                             std::string(toString(e.kind)).c_str(), e.time, energy, now);
            check(now <= energy * (1.0 + 1e-12) + allowance + 1e-15, "energy rose at an event", now - energy);
        }
        energy = now;
    }
    return 0;
}

}  // namespace cuelab::fuzz
