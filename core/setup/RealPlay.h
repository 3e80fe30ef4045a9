#pragma once
// Values beyond real play (CONTRACT.md, Extensions version 2: "a value beyond real play but inside
// the bounds loads, and `validate` prints a warning line for it"). SetupBounds (LegalSetup.h) refuses
// only what arithmetic cannot carry; these ranges say what a real table, ball and cue stay within, so
// that a 40 m teaching "table" or a 40 m/s test ball loads and simulates but is pointed out once:
// `cuelab-cli validate` prints each warning on stderr, the window shows them when it opens the file.
// Plain std: no Qt.

#include "LegalSetup.h"

#include <vector>

namespace cuelab {

// Where real play ends (docs/setup-format.md, "Upper bounds": the "real play" column). Each lies well
// beyond real play already; a value above it is legal up to SetupBounds but worth a warning.
struct RealPlay {
    static constexpr double speed = 20.0;           // m/s: shot.speed (a hard break is 11-12 m/s), |ball velocity|
    static constexpr double spin = 2000.0;          // rad/s: |ball spin| (a pool ball rolling at 20 m/s turns at 700 rad/s)
    static constexpr double tableSize = 10.0;       // m: table.length, table.width (a snooker table is 3.569 m)
    static constexpr double cushionHeight = 1.0;    // m: table.cushion_height
    static constexpr double radius = 0.5;           // m: balls[].radius (pool 0.028575 m)
    static constexpr double mass = 5.0;             // kg: balls[].mass (pool 0.17 kg)
    static constexpr double gravity = 100.0;        // m/s^2: physics.gravity (10 g)
    static constexpr double friction = 10.0;        // physics.mu_*, ball_ball.friction, ball_cushion.friction (cloth 0.005-0.4)
    static constexpr double heading = 3600.0;       // degrees: |shot.heading| (ten turns)
    static constexpr double cueMass = 5.0;          // kg: shot.cue_mass (a cue is about 0.5 kg)
    static constexpr double frameDt = 10.0;         // s: simulation.frame_dt
    static constexpr double maxTime = 86400.0;      // s: simulation.max_time (a day; the default is 600 s)
};

// A value beyond real play: the same shape as a problem (path, ball, message), but the setup loads.
// message: "40 m is beyond real play (up to 10 m); it loads and simulates as given".
using SetupWarning = SetupProblem;

// Every value of `setup` beyond RealPlay, in the order the file format reads it (table, physics,
// balls, shot, simulation). Values that are illegal anyway (not finite, beyond SetupBounds) are the
// validator's, not warned about here.
std::vector<SetupWarning> setupWarnings(const Setup& setup);

}  // namespace cuelab
