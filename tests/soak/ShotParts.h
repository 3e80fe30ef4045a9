#pragma once
// The parts the random shot classes share (RandomShots.cpp, ShotClasses.cpp): the random stream, the
// physics draw, placing a ball where the validator allows it, and the strike.

#include "RandomShots.h"

#include "Table.h"

#include <cstdint>
#include <random>
#include <vector>

namespace cuelab::soak::detail {

// A uniform stream that gives the same numbers with every standard library: the 53 high bits of
// mt19937_64 (whose sequence the standard fixes), not std::uniform_real_distribution (whose
// algorithm it leaves to the library).
class Random {
public:
    explicit Random(std::uint64_t seed) : engine_(seed) {}
    double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }          // [0, 1)
    double uniform(double a, double b) { return a + (b - a) * uniform(); }                  // [a, b)
    bool chance(double p) { return uniform() < p; }
    std::size_t pick(std::size_t n) { return std::min(n - 1, static_cast<std::size_t>(uniform() * double(n))); }
    double angle() { return 2.0 * M_PI * uniform(); }  // rad, [0, 2 pi)

private:
    std::mt19937_64 engine_;
};

// The physics of a random shot: both ball-ball laws and friction kinds, every cushion model of the
// registry with its own parameters (mathavan2010 with a modest step count), the cloth's friction
// within its measured range.
void randomPhysics(Random& rng, PhysicsParams& p);
// The same over the whole legal range (wideRandomShot): ball-ball restitution 0.5-1 (a fifth exactly
// 1, elastic balls), cushion restitution 0.4-1 (a tenth exactly 1) and friction 0-0.4, ball-ball
// friction 0-0.2, the cloth's mu_s 0.05-0.5, mu_r 0.001-0.05, mu_sp 0.001-0.1.
void randomPhysicsWide(Random& rng, PhysicsParams& p);

// A ball radius for the setup: the table's, or (when `unequal`) within 15 % of it, its mass in
// proportion to its volume.
struct BallSize {
    double radius = 0.0;  // m
    double mass = 0.0;    // kg
};
BallSize drawSize(Random& rng, const Table& t, bool unequal);

// A place for a new ball of radius r of the kind asked for (it may be illegal: addBall asks the
// validator).
Vec2 candidate(Placement kind, const Table& t, const Setup& s, double r, Random& rng);

// A Placement drawn with the property generator's weights (random 45 %, frozen 25 %, cushion 12 %,
// jaw 10 %, squeezed 8 %).
Placement drawPlacement(Random& rng, const Table& t);

// Appends a ball with id `id` at p if the validator allows it there; true when it did.
bool addBall(Setup& s, const std::string& id, const Vec2& p, const BallSize& size);

// Places balls as drawPlacement says until the setup has `count` (at most 1000 tries), counting each
// placement kind in shot.placed.
void placeBalls(Random& rng, RandomShot& shot, const Table& t, int count, bool unequal);

// Sets some balls moving: sliding, rolling (perhaps with side spin) or only spinning, up to vmax.
// Returns whether any ball moves.
bool setMoving(Random& rng, Setup& s, double share, double vmax);

// A shot on ball `ball`: cue speed in [vmin, vmax] m/s, the tip within 0.6 R of the centre, sometimes
// elevated up to 30 degrees, sometimes with squirt (an end mass of m / 30).
CueStrike randomStrike(Random& rng, const Setup& s, std::size_t ball, double vmin, double vmax);

// The heading (degrees) from a to b.
double headingTo(const Vec2& a, const Vec2& b);

// The class generators (RandomShots.cpp: Property, Moving; ShotClasses.cpp: the others). Each fills
// shot.setup (its table kind already set) and what it counts.
void propertyShot(Random& rng, RandomShot& shot, bool unequal);
void movingShot(Random& rng, RandomShot& shot, bool unequal);
void clusterShot(Random& rng, RandomShot& shot, bool unequal);
void railShot(Random& rng, RandomShot& shot, bool unequal);
// `anywhere`: the cue ball anywhere on the table, aimed at any ball of the rack (wideRandomShot).
void breakShot(Random& rng, RandomShot& shot, bool anywhere = false);
void elevatedShot(Random& rng, RandomShot& shot, bool unequal);

}  // namespace cuelab::soak::detail
