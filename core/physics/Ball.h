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
};

std::string_view toString(MotionState s);  // "stationary", "spinning", "sliding", "rolling", "pocketed"
bool parseMotionState(std::string_view text, MotionState& out);

struct BallState {
    Vec2 position = Vec2::Zero();  // m, centre of the ball in the table frame
    Vec2 velocity = Vec2::Zero();  // m/s
    Vec3 spin = Vec3::Zero();      // rad/s, angular velocity (wx, wy, wz)
    MotionState motion = MotionState::Stationary;
    int pocket = -1;               // index into Table::pockets when motion == Pocketed, else -1
};

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

// The motion state that the numbers of `s` describe (Pocketed is kept as it is).
MotionState classify(const BallState& s, double radius);

}  // namespace cuelab
