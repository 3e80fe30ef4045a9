#pragma once
// Synthetic recordings for the tests (issue 24): simulate a known shot, sample every ball at 50 Hz,
// add tracking noise of a known size from a fixed seed, and drop some samples, so that a fit has a
// true answer to find. Deterministic on every platform: the noise comes from std::mt19937_64 (whose
// sequence the standard fixes) through Box-Muller written out here (std::normal_distribution is not
// the same on every standard library).

#include "Recording.h"
#include "Setup.h"
#include "Simulation.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace cuelab::test {

struct SamplingOptions {
    double rate = 50.0;           // Hz
    double duration = 3.0;        // s, the recording's length
    double noise = 0.005;         // m, standard deviation of each coordinate's tracking error
    double dropFraction = 0.1;    // of the samples after the first, dropped at random
    std::uint64_t seed = 24;
};

inline double uniform01(std::mt19937_64& rng)
{
    return (static_cast<double>(rng() >> 11) + 0.5) * (1.0 / 9007199254740992.0);  // (0, 1), 53 bits
}

inline double gaussian(std::mt19937_64& rng)
{
    const double u = uniform01(rng), v = uniform01(rng);
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}

// The recording of `setup`'s shot: every ball sampled at `rate` from t = 0 to `duration` (the first
// and last samples always kept), each coordinate with normal noise of `noise` metres.
inline Recording synthesize(const Setup& setup, const SamplingOptions& o = {})
{
    SimulationOptions so;
    so.until = o.duration;
    const SimulationResult run = simulate(setup, so);
    std::mt19937_64 rng(o.seed);
    Recording rec;
    rec.name = "synthetic";
    rec.table = setup.table;
    const int frames = static_cast<int>(std::lround(o.duration * o.rate));
    for (std::size_t i = 0; i < setup.balls.size(); ++i) {
        RecordedBall ball;
        ball.id = setup.balls[i].id;
        for (int k = 0; k <= frames; ++k) {
            const double t = k / o.rate;
            const bool keep = k == 0 || k == frames || uniform01(rng) >= o.dropFraction;
            const Vec2 p = run.stateAt(static_cast<int>(i), std::min(t, run.endTime)).position;
            const Vec2 noisy = p + o.noise * Vec2(gaussian(rng), gaussian(rng));
            if (keep) ball.samples.push_back({t, noisy});
        }
        rec.balls.push_back(std::move(ball));
    }
    return rec;
}

// A three-cushion-like shot on a carom table: the cue ball "1" cuts "2" thin, then goes round the
// table off several cushions; "3" stays (or is hit late). Every strike key shows in the paths: the
// heading in the cut, the speed in the distances, the height in the cue ball's path after the
// contact, the side in the angles off the cushions.
inline Setup caromShot()
{
    Setup s;
    s.name = "synthetic carom shot";
    s.table.kind = TableKind::Carom;
    const Table t = makeTable(s.table);
    const auto ball = [&](const char* id, double x, double y) {
        Ball b;
        b.id = id;
        b.radius = t.ballRadius;
        b.mass = t.ballMass;
        b.state.position = Vec2(x, y);
        return b;
    };
    s.balls = {ball("1", 0.70, 0.50), ball("2", 1.60, 0.80), ball("3", 2.30, 0.30)};
    s.physics.muRoll = 0.006;
    s.physics.muSlide = 0.15;
    CueStrike shot;
    shot.ball = "1";
    shot.headingDeg = 16.0;
    shot.speed = 3.0;
    shot.side = 0.25;
    shot.height = 0.2;
    s.shot = shot;
    return s;
}

}  // namespace cuelab::test
