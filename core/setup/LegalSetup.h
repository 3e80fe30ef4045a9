#pragma once
// What a legal setup is, written once (CONTRACT.md, "A file is refused ... when"): every value rule
// (finite numbers within safe bounds (SetupBounds), radius and mass > 0, frictions >= 0,
// restitutions in [0, 1], unique non-empty ids,
// a shot that names a ball with its tip on the ball, ...) and the table geometry (rails with room
// for their pockets, cushions lower than the balls, every ball on the playing surface, in no pocket,
// overlapping no cushion, jaw or other ball by more than kOverlapTolerance).
//
// The loader (core/io) parses types and keys and then asks this validator, only formatting its
// messages; the editor validates each edit with it directly; the sweep validates each overridden
// setup. Plain std + Eigen: no Qt.

#include "Setup.h"

#include <optional>
#include <string>
#include <vector>

namespace cuelab {

// Two bodies may overlap by at most this much: a frozen rack touches "exactly" only up to rounding.
inline constexpr double kOverlapTolerance = 1e-9;  // m (CONTRACT.md)

// Upper bounds of the numbers with a physical meaning (docs/setup-format.md, "Upper bounds"), set
// where arithmetic stops being safe, never where play stops being realistic (CONTRACT.md, Extensions
// version 2: every file legal under version 1 stays legal; at least lengths 1 km, speeds 1000 m/s,
// spins 1e5 rad/s). A finite but absurd value (a shot at 1e300 m/s) is refused like a non-finite one,
// instead of giving overflowing, "null" results. A value beyond real play but within these bounds
// loads; RealPlay.h names those ranges and warns about such values.
struct SetupBounds {
    static constexpr double speed = 1000.0;         // m/s: shot.speed, |ball velocity|
    static constexpr double spin = 1e5;             // rad/s: |ball spin|
    static constexpr double tableSize = 1000.0;     // m: table.length, table.width
    static constexpr double cushionHeight = 1000.0; // m: table.cushion_height (and below 2R of every ball anyway)
    static constexpr double radius = 500.0;         // m: balls[].radius (a 1 km ball: the largest a 1 km table holds)
    static constexpr double mass = 1e6;             // kg: balls[].mass
    static constexpr double gravity = 1e4;          // m/s^2: physics.gravity (1000 g)
    static constexpr double friction = 1000.0;      // physics.mu_*, ball_ball.friction, ball_cushion.friction
    static constexpr double heading = 1e6;          // degrees: |shot.heading|
    static constexpr double cueMass = 1e6;          // kg: shot.cue_mass; end_mass <= cue_mass
    static constexpr double frameDt = 1e6;          // s: simulation.frame_dt
    static constexpr double maxTime = 1e6;          // s: simulation.max_time (11.6 days; the default is 600 s)
};

// One broken rule.
struct SetupProblem {
    std::string path;     // JSON path of the culprit: "balls[2].position", "physics.mu_roll"; "" = the whole setup
    std::string ballId;   // the ball concerned ("cue"), empty when the rule is not about one ball
    int ballIndex = -1;   // its index in Setup::balls, -1 when none
    std::string message;  // a sentence a person can act on, naming the ball by its id:
                          // "ball \"cue\" overlaps ball \"7\" by 2.1 mm"
};

// Every problem of `setup`, in the order the file format reads it: table, physics, balls, shot,
// simulation, then the geometry (rails, then ball by ball). Empty when the setup can be simulated.
// The geometry of a table whose own numbers are broken is not checked (there is no table to check
// against), nor the place of a ball whose radius or position is broken.
std::vector<SetupProblem> validateSetup(const Setup& setup);

// The first of validateSetup's problems, or nullopt; stops looking at the first.
std::optional<SetupProblem> firstSetupProblem(const Setup& setup);

// The problems of one ball only (its values, its id against the others, its place on the table and
// against the other balls): what a drag or a ball edit needs to know, quickly.
std::vector<SetupProblem> validateBall(const Setup& setup, std::size_t index);

// A length for a message, in the unit that keeps it readable: "2.1 mm", "35.0 µm", "4.2 nm".
std::string describeLength(double metres);

// A number for a message, as printf's %g writes it: "0.03", "-1", "1e-05", "nan".
std::string describeNumber(double value);

}  // namespace cuelab
