#include "BallBallCollision.h"

#include "Motion.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cuelab {

double ballBallFriction(const PhysicsParams& p, double vRel)
{
    if (p.ballBallFrictionKind == BallBallFriction::Alciatore) return 9.951e-3 + 0.108 * std::exp(-1.088 * vRel);
    return p.ballBallFriction;
}

BallBallResult resolveBallBall(const BallBallBody& a, const BallBallBody& b, const PhysicsParams& p,
                               BallBallTrace* trace)
{
    BallBallResult r;
    const Vec2 d = b.state.position - a.state.position;
    r.normal = d / d.norm();
    r.contactPoint = a.state.position + a.radius * r.normal;
    r.approachSpeed = (a.state.velocity - b.state.velocity).dot(r.normal);
    r.a = a.state;
    r.b = b.state;

    const double invMass = 1.0 / a.mass + 1.0 / b.mass;
    const double normalImpulse = std::max(0.0, (1.0 + p.ballBallRestitution) * r.approachSpeed / invMass);  // N s
    const Vec3 n(r.normal.x(), r.normal.y(), 0.0);
    Vec3 impulseOnA = -normalImpulse * n;

    Vec3 tangentialOnA = Vec3::Zero();
    if (p.ballBallModel == BallBallModel::Frictional && normalImpulse > 0.0) {
        // Velocities of the two contact points, v + w x (R n) for a and v + w x (-R n) for b.
        const Vec3 va(a.state.velocity.x(), a.state.velocity.y(), 0.0);
        const Vec3 vb(b.state.velocity.x(), b.state.velocity.y(), 0.0);
        const Vec3 contactA = va + a.state.spin.cross(a.radius * n);
        const Vec3 contactB = vb - b.state.spin.cross(b.radius * n);
        Vec3 slip = contactA - contactB;
        slip -= slip.dot(n) * n;  // the tangential part: the normal part is the approach
        const double slipSpeed = slip.norm();
        if (slipSpeed > 0.0) {
            const double compliance = 3.5 * invMass;  // 1/ma + 1/mb + Ra^2/Ia + Rb^2/Ib (1/kg)
            const double stopping = slipSpeed / compliance;
            const double mu = ballBallFriction(p, slipSpeed);
            const double magnitude = std::min(mu * normalImpulse, stopping);
            tangentialOnA = -(magnitude / slipSpeed) * slip;
            if (trace) {
                trace->friction = mu;
                trace->coulombLimit = mu * normalImpulse;
                trace->stoppingImpulse = stopping;
                trace->coulombLimited = mu * normalImpulse < stopping;
            }
        }
        if (trace) {
            trace->frictional = true;
            trace->slip = slip;
            trace->slipSpeed = slipSpeed;
        }
    }
    if (trace) {
        trace->inverseMass = invMass;
        trace->normalImpulse = normalImpulse;
        trace->tangentialImpulse = tangentialOnA;
    }
    impulseOnA += tangentialOnA;

    r.a.velocity += impulseOnA.head<2>() / a.mass;
    r.b.velocity -= impulseOnA.head<2>() / b.mass;
    // Torques of the tangential impulse about each centre: (R n) x J on a, (-R n) x (-J) on b.
    r.a.spin += (a.radius * n).cross(tangentialOnA) / ballInertia(a.mass, a.radius);
    r.b.spin += (b.radius * n).cross(tangentialOnA) / ballInertia(b.mass, b.radius);
    r.a.motion = classify(r.a, a.radius);
    r.b.motion = classify(r.b, b.radius);
    r.impulse = impulseOnA;
    return r;
}

}  // namespace cuelab
