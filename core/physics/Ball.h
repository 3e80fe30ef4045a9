#pragma once
// A ball: fixed properties (id, radius, mass) and its changing kinematic state.

#include "Types.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace cuelab {

// Motion states of PHYSICS.md. The label must agree with the numbers: a "sliding" ball whose slip
// is zero is rolling. classify() below decides from the numbers.
enum class MotionState : std::uint8_t {
    Stationary,  // v = 0, w = 0
    Spinning,    // v = 0, only wz != 0
    Sliding,     // slip u = v + R (z x w) != 0
    Rolling,     // u = 0, v != 0
    Pocketed,    // off the table; pocket index in BallState::pocket
    Airborne,    // off the cloth: z > 0, or on it and leaving it (vz > 0); flies in closed form (Flight.h)
    OffTable,    // left the table over a cushion (`ball-off-table`); out of play like a pocketed ball
};

// "stationary", "spinning", "sliding", "rolling", "pocketed", "airborne", "off-table"
std::string_view toString(MotionState s);
bool parseMotionState(std::string_view text, MotionState& out);

struct BallState {
    Vec2 position = Vec2::Zero();  // m, centre of the ball in the table frame
    Vec2 velocity = Vec2::Zero();  // m/s
    Vec3 spin = Vec3::Zero();      // rad/s, angular velocity (wx, wy, wz)
    MotionState motion = MotionState::Stationary;
    int pocket = -1;               // index into Table::pockets when motion == Pocketed, else -1
    // The centre's height above its resting height (CONTRACT.md "Airborne balls": 0 on the cloth) and
    // its vertical velocity, + up. Both stay exactly 0 for a ball that never leaves the cloth, so
    // everything computed on the cloth is what it was before balls could fly.
    double z = 0.0;   // m, >= 0
    double vz = 0.0;  // m/s
};

// m: a height within this of the cloth counts as on it, and a ball is never evaluated below -this
// (the flight's own closed forms keep z >= 0 to rounding; tst_airborne checks 1e-12).
inline constexpr double kHeightTolerance = 1e-12;

// Out of play: in a pocket or off the table.
inline bool isOutOfPlay(MotionState m) { return m == MotionState::Pocketed || m == MotionState::OffTable; }

struct Ball {
    std::string id;                // unique, non-empty ("cue", "1", ...)
    double radius = 0.028575;      // m (WPA 2.25 in)
    double mass = 0.170097;        // kg (WPA 6 oz)
    BallState state;
};

// Slip velocity of the cloth contact point: u = v + R (z x w) = (vx - R wy, vy + R wx).
inline Vec2 slipVelocity(const BallState& s, double radius)
{
    return Vec2(s.velocity.x() - radius * s.spin.y(), s.velocity.y() + radius * s.spin.x());
}

// Thresholds below which a speed counts as zero. They only classify states that are zero up to
// rounding; every transition time itself is computed in closed form.
inline constexpr double kSpeedEpsilon = 1e-11;  // m/s
inline constexpr double kSpinEpsilon = 1e-11;   // rad/s

// The motion state that the numbers of `s` describe (Pocketed and OffTable are kept as they are).
// Airborne when z > kHeightTolerance or vz > 0; a ball on the cloth with vz < 0 is labelled by its
// horizontal numbers (it is an impact now, which the simulator resolves at once).
MotionState classify(const BallState& s, double radius);

}  // namespace cuelab
