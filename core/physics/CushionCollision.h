#pragma once
// Ball-cushion collision, for a straight cushion nose or a jaw tip (PHYSICS.md, "Ball-cushion").

#include "Ball.h"
#include "Parameters.h"
#include "Types.h"

namespace cuelab {

struct CushionResult {
    BallState after;              // labelled by classify
    double approachSpeed = 0.0;   // m/s, -(v . N) before; > 0 when approaching
    Vec3 impulse = Vec3::Zero();  // N s, on the ball, table frame
};

// `normal` is the unit normal of the cushion at the contact, pointing from the cushion to the ball's
// centre (a segment's normal; for a jaw tip, from the jaw's centre to the ball's). `noseHeight` is
// the height of the contact line above the cloth (m). Dispatches on p.ballCushionModel:
// - Mirror (the 2011 report): v' = v - (1 + e)(v.N)N, spins unchanged.
// - Han2005: see hanCushion().
CushionResult resolveCushion(const BallState& before, const Vec2& normal, double radius, double mass,
                             double noseHeight, const PhysicsParams& p);

// Han 2005, "Dynamics in carom and three cushion billiards" (J. Mech. Sci. Tech. 19(4)), exactly as
// PHYSICS.md writes it: the contact lies above the equator at theta_a = asin(h/R - 1); in the rail
// frame (x into the rail, y = z x x, z up) the compression impulse PzE = (1 + e) m vx cos(theta_a)
// and Coulomb friction (mu_c) act on the slip of the contact point, stopping it when it can. The ball
// leaves sliding; a head-on ball without spin rebounds at (1 + e) cos^2 + (2/7) sin^2 - 1 of its speed.
CushionResult hanCushion(const BallState& before, const Vec2& normal, double radius, double mass,
                         double noseHeight, double restitution, double friction);

}  // namespace cuelab
