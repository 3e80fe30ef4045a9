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
    Vec2 normal = Vec2::Zero();   // unit, from a towards b
    Vec2 contactPoint = Vec2::Zero();
    double approachSpeed = 0.0;   // m/s, (va - vb) . n before; > 0 when approaching
    Vec3 impulse = Vec3::Zero();  // N s, on a (normal plus tangential, table frame)
};

// The intermediate numbers of resolveBallBall, for core/explain (filled only when asked for).
struct BallBallTrace {
    double inverseMass = 0.0;       // 1/kg, 1/ma + 1/mb
    double normalImpulse = 0.0;     // N s, Pn = (1 + e) (va - vb).n / (1/ma + 1/mb), >= 0
    bool frictional = false;        // the tangential part below was computed
    Vec3 slip = Vec3::Zero();       // m/s, tangential relative velocity of the contact points (a minus b)
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

// Normal impulse with restitution e for general masses, Pn = (1 + e) m_eff (va - vb).n with
// m_eff = ma mb / (ma + mb); for equal masses this is PHYSICS.md's Delta = (1 + e)/2 ((va - vb).n) n.
// The frictional model adds a tangential impulse opposite to the slip of the contact points, at most
// mu_b Pn (Coulomb) and never more than what stops that slip: an impulse J at the contact changes the
// slip by J (1/ma + 1/mb + Ra^2/Ia + Rb^2/Ib) = J (7/2)(1/ma + 1/mb) for solid spheres (m/7 for equal
// masses). The slip has a vertical part (from wx, wy); the impulse acts on the spins in 3D while
// its vertical linear part is taken up by the cloth (discarded), which only removes energy.
// The balls need not approach: a caller only resolves approaching pairs.
BallBallResult resolveBallBall(const BallBallBody& a, const BallBallBody& b, const PhysicsParams& p,
                               BallBallTrace* trace = nullptr);

}  // namespace cuelab
