#pragma once
// Ball-ball collision: an instantaneous impulse at the contact point (PHYSICS.md, "Ball-ball").

#include "Ball.h"
#include "Parameters.h"
#include "Types.h"

namespace cuelab {

struct BallBallBody {
    BallState state;
    double radius = 0.0;  // m
    double mass = 0.0;    // kg
};

struct BallBallResult {
    BallState a, b;               // just after (labelled by classify)
    Vec2 normal = Vec2::Zero();   // unit, horizontal, from a towards b (the line of centres seen from above)
    Vec3 normal3 = Vec3::Zero();  // unit 3-D contact normal from a's centre to b's: contactNormal(normal, Ra, Rb)
    Vec2 contactPoint = Vec2::Zero();  // m, the contact r_a + R_a normal3 projected on the cloth plane
    double approachSpeed = 0.0;   // m/s, (va - vb) . normal3 before; > 0 when approaching
    Vec3 impulse = Vec3::Zero();  // N s, on a (normal plus tangential, table frame; its z part goes into the cloth)
};

// The intermediate numbers of resolveBallBall, for core/explain (filled only when asked for).
struct BallBallTrace {
    double inverseMass = 0.0;       // 1/kg, 1/ma + 1/mb
    double level = 1.0;             // |n_xy| = 2 sqrt(Ra Rb) / (Ra + Rb): 1 for equal radii
    double normalCompliance = 0.0;  // 1/kg, level^2 (1/ma + 1/mb): the approach speed lost per unit of Pn
    double normalImpulse = 0.0;     // N s, Pn = (1 + e) (va - vb).n / normalCompliance, >= 0
    bool frictional = false;        // the tangential part below was computed
    Vec3 slip = Vec3::Zero();       // m/s, tangential relative velocity of the contact points (a minus b);
                                    // for unequal radii after the normal impulse (see resolveBallBall)
    double slipSpeed = 0.0;         // m/s, |slip|
    double friction = 0.0;          // mu_b used (fixed, or Alciatore's fit at slipSpeed)
    double coulombLimit = 0.0;      // N s, mu_b Pn
    double stoppingImpulse = 0.0;   // N s, the tangential impulse that stops the slip: |slip| / (7/2 (1/ma + 1/mb))
    bool coulombLimited = false;    // the tangential impulse is mu_b Pn (the slip does not stop)
    Vec3 tangentialImpulse = Vec3::Zero();  // N s, on a
};

// Friction coefficient between the balls at relative surface speed vRel (m/s): fixed, or
// Alciatore's fit mu_b = 9.951e-3 + 0.108 exp(-1.088 vRel) (TP A-14).
double ballBallFriction(const PhysicsParams& p, double vRel);

// The 3-D contact normal of two balls resting on the cloth, from a's centre (height ra) to b's
// (height rb), given the unit horizontal direction u from a to b:
//     n = (u touchDistance(ra, rb), rb - ra) / (ra + rb),   |n| = 1,
// level, (u, 0), for equal radii (bit for bit).
Vec3 contactNormal(const Vec2& u, double ra, double rb);

// Normal impulse with restitution e for general masses, Pn = (1 + e) m_eff (va - vb).n with
// m_eff = ma mb / (ma + mb); for equal masses this is PHYSICS.md's Delta = (1 + e)/2 ((va - vb).n) n.
// The frictional model adds a tangential impulse opposite to the slip of the contact points, at most
// mu_b Pn (Coulomb) and never more than what stops that slip: an impulse J at the contact changes the
// slip by J (1/ma + 1/mb + Ra^2/Ia + Rb^2/Ib) = J (7/2)(1/ma + 1/mb) for solid spheres (m/7 for equal
// masses). The slip has a vertical part (from wx, wy); the impulse acts on the spins in 3D while
// its vertical linear part is taken up by the cloth (discarded), which only removes energy.
// The balls need not approach: a caller only resolves approaching pairs.
//
// Balls of unequal radius (PHYSICS.md, "Balls of unequal radius on the cloth"): the normal n is
// contactNormal(u, Ra, Rb), tilted by nz = (Rb - Ra)/(Ra + Rb) out of the cloth plane, with the level
// part n_xy = c u, c = 2 sqrt(Ra Rb)/(Ra + Rb) (c^2 = 1 - nz^2). The contact is r_a + Ra n, the
// impulse acts along n, and the balls stay on the cloth: the cloth takes every vertical impulse and
// the centres' vertical velocities stay 0 (the smaller ball is pressed into the cloth; the larger one
// is pulled down by J |nz|, where a real one would hop by (J nz / m)^2 / (2 g), about 0.1 mm at
// 2 m/s: CueLab has no airborne ball, as for the vertical parts of the cue strike and of friction).
// So an impulse -J n on a and +J n on b moves only the horizontal velocities, by -+J n_xy / m, and
// adds no spin (it passes through both centres); the approach speed along n,
//     v_n = (va - vb) . n = c (va - vb) . u,
// falls by J (n_xy . n_xy)(1/ma + 1/mb) = J c^2 (1/ma + 1/mb). Newton's restitution along n
// (v_n' = -e v_n) then gives
//     J = (1 + e) v_n / (c^2 (1/ma + 1/mb)):
// held on the cloth, the pair's effective mass along n is 1 / (c^2 (1/ma + 1/mb)), larger than the
// free m_eff. Its horizontal part J c u = (1 + e) ((va - vb) . u) / (1/ma + 1/mb) u is exactly the
// level collision's along u: without friction the tilt changes when and where the balls touch, not
// how they leave. Horizontal momentum is kept (the cloth pushes only vertically) and, the cloth doing
// no work, the energy lost is (1 - e^2) v_n^2 / (2 c^2 (1/ma + 1/mb)).
// With friction the normal impulse itself changes the tangential slip when n is tilted (it moves the
// centres horizontally, and the tangent plane is not vertical): the slip is therefore taken after the
// normal impulse, and the tangential impulse P_t <= |s| / (7/2 (1/ma + 1/mb)) against it never
// reverses it. Energy cannot rise: an impulse P at the contact changes the energy by
// P . (w_before + w_after)/2, with w the relative velocity of the contact points just before and
// just after it. Taken in two stages, the normal impulse loses (1 - e^2) v_n^2 / (2 c^2 (1/ma + 1/mb))
// and the tangential one at least P_t |s| / 2, since on the tangent plane the compliance of balls
// held on the cloth, (1/ma + 1/mb)(P_xy + 5/2 (1 - n n^T)) with P_xy the horizontal projection, is
// at most 7/2 (1/ma + 1/mb).
// For equal radii (nz = 0) the normal impulse does not change the tangential slip and every number
// is computed as before unequal radii were handled, bit for bit.
BallBallResult resolveBallBall(const BallBallBody& a, const BallBallBody& b, const PhysicsParams& p,
                               BallBallTrace* trace = nullptr);

}  // namespace cuelab
