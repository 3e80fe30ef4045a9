#pragma once
// A ball off the cloth (PHYSICS.md, "Airborne balls, jumps and massé"; CONTRACT.md, "Airborne balls").
//
// In flight a ball feels gravity only (no air drag; the Magnus force is negligible on a pool ball):
//     x(t) = x0 + vx t,   y(t) = y0 + vy t,   z(t) = z0 + vz t - g t^2 / 2,
// and its spin is constant (no cloth, so no sliding, rolling or spin friction). Every coordinate is a
// polynomial of degree two or less, so every time of impact stays a polynomial root.
//
// The simulator flies an airborne ball with these functions (Motion.cpp, AirborneLoop.cpp).

#include "Ball.h"
#include "Motion.h"
#include "Types.h"

namespace cuelab {

// A ball's state with its height: BallState carries z (the centre above its resting height R,
// CONTRACT.md: 0 on the cloth) and vz (+ up) since the simulator flies balls; the name stays for the
// building blocks that speak of flight.
using AirState = BallState;

// The velocity in space, (vx, vy, vz).
inline Vec3 velocity3(const AirState& s) { return Vec3(s.velocity.x(), s.velocity.y(), s.vz); }

// Two balls' contact measured in space (their centres at heights R + z): the unit normal from a's
// centre to b's, the gap |d| - (Ra + Rb), the relative normal speed (v_b - v_a) . n (> 0 parting) and
// the curvature |v_t|^2 / |d| with which their tangential motion opens the gap. The held contacts of a
// flying ball (AirHold.cpp, HeldContacts.cpp) share it.
struct SpaceContact {
    Vec3 normal = Vec3::Zero();
    double distance = 0.0;     // m, |d| (0: the normal is undefined)
    double gap = 0.0;          // m
    double normalSpeed = 0.0;  // m/s
    double tangentSpeed2 = 0.0;  // m^2/s^2, |v_t|^2
    double curvature() const { return tangentSpeed2 / distance; }
};
SpaceContact spaceContact(const AirState& a, double ra, const AirState& b, double rb);

// The state `s` at height z with vertical velocity vz.
AirState lifted(const BallState& s, double z = 0.0, double vz = 0.0);

// Flying: above the cloth, or on it and leaving it (vz > 0). A ball on the cloth with vz < 0 is an
// impact now (resolve/TableModel.h); with vz = 0 it is on the cloth.
bool isAirborne(const AirState& s);

// The path of the centre in space: c(s) = c0 + c1 s + c2 s^2, with z the height of the centre above
// the cloth (R on the cloth, not the contract's z), so that balls of unequal radius and cushion noses
// at their height compare directly. A flying ball has c2 = (0, 0, -g/2); a ball on the cloth has
// its Path's c2 and a constant height R.
struct SpacePath {
    Vec3 c0 = Vec3::Zero();  // m
    Vec3 c1 = Vec3::Zero();  // m/s
    Vec3 c2 = Vec3::Zero();  // m/s^2
    Vec3 at(double s) const { return c0 + s * (c1 + s * c2); }
    Vec3 velocityAt(double s) const { return c1 + (2.0 * s) * c2; }
    SpacePath shifted(double s0) const { return SpacePath{at(s0), velocityAt(s0), c2}; }
};
// A ball on the cloth moving along `p` (Motion.h's pathOf), its centre at height R.
SpacePath clothPath(const Path& p, double radius);
// A flying ball (the flight's closed form above), from its state now.
SpacePath flightPath(const AirState& s, double radius, double gravity);

// The state dt seconds later in flight (no clamping: past the landing z would be negative, so a
// caller stops at landingTime). Horizontal motion uniform, spin constant.
AirState fly(const AirState& s, double gravity, double dt);

// Seconds from now until the ball comes down to the cloth (z = 0 with vz < 0): the positive root of
// z + vz t - g t^2 / 2 = 0, t = (vz + sqrt(vz^2 + 2 g z)) / g, which is exactly 2 vz / g from the
// cloth (z = 0). 0 for a ball on the cloth that is not leaving it (vz <= 0); kNever if g <= 0.
double landingTime(const AirState& s, double gravity);
// The vertical speed at that landing, sqrt(vz^2 + 2 g z) (m/s, >= 0).
double landingSpeed(const AirState& s, double gravity);

// Seconds until the top of the flight, vz / g (0 once the ball comes down), and the height z of
// the top above the resting height, z + vz^2 / (2 g) (vz^2 / (2 g) from the cloth).
double apexTime(const AirState& s, double gravity);
double apexHeight(const AirState& s, double gravity);

// A flying ball held against a body (a ball on the cloth it slides down; docs/airborne.md, "Held in
// the air"): besides gravity it carries over its segment a constant contact force per unit mass
// `push` (m/s^2, 3-D), so its path is still a quadratic, c2 = (push - g z)/2, and its landing the root
// of z + vz t + (push_z - g) t^2 / 2 = 0 (landingTime with the gravity g - push_z; kNever when the push
// holds it up). A zero push gives exactly the free flight above.
SpacePath heldFlightPath(const AirState& s, double radius, double gravity, const Vec3& push);
double heldLandingTime(const AirState& s, double gravity, const Vec3& push);
// The state dt later, held at the landing (z = 0 there and after), as evolve holds a free flight.
AirState flyHeld(const AirState& s, double gravity, const Vec3& push, double dt);

// Kinetic energy (translation in 3-D and rotation) plus the potential energy m g z above the resting
// height (J): constant in flight.
double mechanicalEnergy(const AirState& s, double radius, double mass, double gravity);

}  // namespace cuelab
