#pragma once
// The route of a shot as a player names it, read off its noise-free simulation:
//   jump           an elevated cue (3° or more) and the struck ball flies (thrown up by the cloth
//                  at more than 0.5 m/s) before its first contact
//   masse          a steep cue (elevation of 30° or more) that does not jump: the path curves
//   combination    the struck ball's first contact is not the ball the goal pots
//   kick           the struck ball touches a cushion before its first contact
//   bank N cushions  the potted ball touches N straight cushions before it drops (jaws not counted)
//   direct         none of these
// checked in this order (a jump is named a jump even when it is also a combination).

#include "ShotOutcome.h"
#include "Simulation.h"

#include <optional>
#include <string>

namespace cuelab::solve {

constexpr double kMasseElevationDeg = 30.0;  // degrees: a steeper cue curves the path visibly
constexpr double kJumpElevationDeg = 3.0;    // degrees: below this the cue is level (its noise aside)
// m/s: thrown up this fast, a ball rises v²/2g = 1.3 cm: a flight, not a hop of the cloth.
constexpr double kJumpTakeOffSpeed = 0.5;

struct RouteInfo {
    std::string route;
    std::optional<std::string> firstContact;  // the id of the ball met first
    std::string pocket;                       // the id of the pocket the target fell in, "" when none
};

// `target`: the ball the goal pots (index), -1 when it pots none (the first object ball pocketed,
// if any, is then the one whose banks count).
RouteInfo routeOf(const SimulationResult& result, const ShotOutcome& outcome, int target, double elevationDeg);

}  // namespace cuelab::solve
