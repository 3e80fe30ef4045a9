#include "BallBallCollision.h"

#include "BallContact.h"
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

Vec3 contactNormal(const Vec2& u, double ra, double rb)
{
    // For ra == rb: c = (ra + rb)/(ra + rb) = 1 and nz = 0/(ra + rb) = 0 exactly, so n = (u, 0).
    const double sum = ra + rb;
    const double c = touchDistance(ra, rb) / sum;
    return Vec3(c * u.x(), c * u.y(), (rb - ra) / sum);
}

BallBallResult resolveBallBall(const BallBallBody& a, const BallBallBody& b, const PhysicsParams& p,
                               BallBallTrace* trace)
{
    BallBallResult r;
    const Vec2 d = b.state.position - a.state.position;
    r.normal = d / d.norm();
    const Vec3 n = contactNormal(r.normal, a.radius, b.radius);
    const double c = touchDistance(a.radius, b.radius) / (a.radius + b.radius);  // |n_xy|, as in contactNormal
    const bool level = a.radius == b.radius;  // then c = 1, n = (normal, 0): the level formulas, bit for bit
    r.normal3 = n;
    // Multiplying by c = 1 (equal radii) is exact: these are the level formulas then.
    r.contactPoint = a.state.position + (a.radius * c) * r.normal;
    r.approachSpeed = c * (a.state.velocity - b.state.velocity).dot(r.normal);
    r.a = a.state;
    r.b = b.state;

    // Held on the cloth, the balls' approach along n falls by c^2 (1/ma + 1/mb) per unit of normal
    // impulse (the header derives it): 1/kg.
    const double invMass = 1.0 / a.mass + 1.0 / b.mass;
    const double compliance = c * c * invMass;
    const double normalImpulse = std::max(0.0, (1.0 + p.ballBallRestitution) * r.approachSpeed / compliance);  // N s
    Vec3 impulseOnA = -normalImpulse * n;

    Vec3 tangentialOnA = Vec3::Zero();
    if (p.ballBallModel == BallBallModel::Frictional && normalImpulse > 0.0) {
        // Velocities of the two contact points, v + w x (R n) for a and v + w x (-R n) for b. A tilted
        // normal impulse changes the tangential slip (its horizontal part moves the centres across
        // the tilted tangent plane), so the slip is taken after it; a level one does not, and the
        // slip is taken from the velocities before, as for equal radii always.
        const Vec2 va2 = level ? a.state.velocity : Vec2(a.state.velocity + impulseOnA.head<2>() / a.mass);
        const Vec2 vb2 = level ? b.state.velocity : Vec2(b.state.velocity - impulseOnA.head<2>() / b.mass);
        const Vec3 va(va2.x(), va2.y(), 0.0);
        const Vec3 vb(vb2.x(), vb2.y(), 0.0);
        const Vec3 contactA = va + a.state.spin.cross(a.radius * n);
        const Vec3 contactB = vb - b.state.spin.cross(b.radius * n);
        Vec3 slip = contactA - contactB;
        slip -= slip.dot(n) * n;  // the tangential part: the normal part is the approach
        const double slipSpeed = slip.norm();
        if (slipSpeed > 0.0) {
            const double tangentialCompliance = 3.5 * invMass;  // 1/ma + 1/mb + Ra^2/Ia + Rb^2/Ib (1/kg)
            const double stopping = slipSpeed / tangentialCompliance;
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
        trace->level = c;
        trace->normalCompliance = compliance;
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
