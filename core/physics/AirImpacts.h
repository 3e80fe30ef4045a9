#pragma once
// Impacts of flying balls in 3-D: against a fixed body along any normal (a cushion's nose edge or
// face, the cloth), and between two balls whose line of centres is tilted (PHYSICS.md, "Airborne
// balls"). The simulator's laws for a flying ball's collisions (AirCollisions.cpp); AirImpactsTrace.h
// gives the explanation (core/explain) their intermediate numbers.
//
// Both are single impulses at the contact point with Newton's restitution along the normal and
// Coulomb friction that never more than stops the tangential slip, so neither adds energy
// (tst_airimpacts checks it).

#include "BallBallCollision.h"
#include "Flight.h"
#include "Parameters.h"
#include "resolve/TableModel.h"

namespace cuelab {

struct FixedImpactResult {
    AirState after;               // `motion` labelled by classify (its horizontal numbers)
    double approachSpeed = 0.0;   // m/s, -(v . n) before (> 0: approaching)
    Vec3 impulse = Vec3::Zero();  // N s, on the ball
    bool slipEnded = false;       // the friction stopped the contact point's tangential slip
};

// A ball against an immovable body touching it at Q = -R n from its centre, `normal` n (unit) pointing
// from the contact to the centre. With the contact point's velocity v_c = v + w x Q (3-D v, with vz):
//   normal:     Pn = -(1 + e) m (v . n) when v . n < 0 (else nothing happens);
//   tangential: the slip u_t = v_c - (v_c . n) n changes by 7/2 Pt / m (any tangent of a solid sphere:
//               1/m + R^2/I), so Pt = -min(mu Pn, 2/7 m |u_t|) u_t / |u_t|.
// The ball gets dv = P / m and dw = Q x P / I (the normal part passes through the centre). With
// n = z this is resolve/FrictionalTable's bounce. For a cushion's nose the normal comes from
// AirborneDetection.h (AirCushionContact::normal), e and mu from the cushion's parameters.
FixedImpactResult resolveFixedImpact(const AirState& before, double radius, double mass, const Vec3& normal,
                                     double restitution, double friction);

struct AirBallBallResult {
    AirState a, b;                // just after, including the cloth's answer below
    Vec3 normal = Vec3::Zero();   // unit, from a's centre to b's, in space
    double approachSpeed = 0.0;   // m/s, (va - vb) . n before (> 0: approaching)
    Vec3 impulse = Vec3::Zero();  // N s, on a, ball on ball (normal plus tangential)
    // A ball on the cloth that the impulse drove downwards is answered by the cloth at once, as at
    // the cue strike (resolveTableImpact): its bounce.
    bool aBounced = false, bBounced = false;
    TableImpactResult aBounce, bBounce;
};

// Two balls touching in space (|c_b - c_a| = Ra + Rb, centres at heights R + z). The impulse along the
// 3-D normal n: Pn = (1 + e) ((va - vb) . n) / (1/ma + 1/mb), with p.ballBallRestitution; when
// p.ballBallModel is Frictional, a tangential impulse against the contact points' slip, at most
// mu_b Pn (ballBallFriction) and at most what stops the slip (compliance 7/2 (1/ma + 1/mb)), as
// resolveBallBall. Unlike resolveBallBall, both balls are free in 3-D: the vertical parts go into vz.
// Then a ball on the cloth (z within kHeightTolerance) left with vz < 0 bounces on it at once.
// Two balls on the cloth with equal radii and no friction give resolveBallBall's velocities (to
// rounding) and no vertical velocity. With friction the slip's vertical part (from wx, wy) gives a
// vertical impulse that resolveBallBall hands to the cloth and this function does not: one ball hops
// a little, the other bounces on the cloth. So a pair that is on the cloth before the collision
// keeps resolveBallBall (old files bit for bit); this is for pairs with a flying ball.
AirBallBallResult resolveAirBallBall(const AirState& a, double ra, double ma, const AirState& b, double rb, double mb,
                                     const PhysicsParams& p);

// A touch with no approach (AirCollisions.cpp, and the explanation alike): the law's `res` of the
// states before `a`, `b` approaches within kRestingSpeed and changes no velocity (no impulse, or one
// lost in rounding). The simulator holds such a pair from the states before, or lets it be.
bool airTouchRests(const AirBallBallResult& res, const AirState& a, const AirState& b);

}  // namespace cuelab
