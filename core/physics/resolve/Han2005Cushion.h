#pragma once
// Han 2005, "Dynamics in carom and three cushion billiards" (J. Mech. Sci. Tech. 19(4)), exactly as
// PHYSICS.md writes it: the contact lies above the equator at theta_a = asin(h/R - 1); in the rail
// frame (x into the rail, y = z x x, z up) the compression impulse PzE = (1 + e) m vx cos(theta_a)
// and Coulomb friction (mu_c) act on the slip of the contact point, stopping it when it can. The ball
// leaves sliding; a head-on ball without spin rebounds at (1 + e) cos^2 + (2/7) sin^2 - 1 of its speed.

#include "resolve/CushionModel.h"

namespace cuelab {

// The intermediate numbers of the Han 2005 model, for core/explain (filled only when asked for).
struct HanTrace {
    double sinA = 0.0, cosA = 0.0;       // of theta_a = asin(h/R - 1)
    Vec2 railX = Vec2::Zero();           // unit, into the rail (-N)
    Vec2 railY = Vec2::Zero();           // unit, z x X, along the rail
    double vx = 0.0, vy = 0.0;           // m/s, velocity in the rail frame
    double wx = 0.0, wy = 0.0, wz = 0.0; // rad/s, spin in the rail frame
    double sx = 0.0, sy = 0.0;           // m/s, slip of the contact point
    double slip = 0.0;                   // m/s, |s|
    double c = 0.0;                      // m/s, normal velocity at the contact (< 0 approaching)
    double A = 0.0, B = 0.0;             // 1/kg, 7/(2m) and 1/m
    double PzE = 0.0;                    // N s, normal impulse, compression and restitution
    double PzS = 0.0;                    // N s, the impulse that stops the slip, |s| / A
    bool sticking = false;               // PzS <= mu PzE: the slip stops
    double PxE = 0.0, PyE = 0.0;         // N s, tangential impulse in the contact frame
    double PX = 0.0, PY = 0.0, PZ = 0.0; // N s, impulse in the rail frame
    double vx1 = 0.0, vy1 = 0.0;         // after, rail frame
    double wx1 = 0.0, wy1 = 0.0, wz1 = 0.0;
};


CushionResult hanCushion(const BallState& before, const Vec2& normal, double radius, double mass,
                         double noseHeight, double restitution, double friction, HanTrace* trace = nullptr);

// The registry's entry point: hanCushion with p.cushionRestitution and p.cushionFriction.
CushionResult han2005Cushion(const CushionContact& contact, const PhysicsParams& p);

}  // namespace cuelab
