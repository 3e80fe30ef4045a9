#include "AirImpacts.h"
#include "AirImpactsTrace.h"

#include "Contact.h"
#include "Detection.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cuelab {

namespace {

void setVelocity3(AirState& s, const Vec3& v)
{
    s.velocity = v.head<2>();
    s.vz = v.z();
}

Vec3 centre3(const AirState& s, double radius) { return Vec3(s.position.x(), s.position.y(), radius + s.z); }

// The cloth answers a ball on it that an impact drove downwards. A ball on it that the impact (or
// the cloth's own rebound) sends up so slowly that its hop would stay within kHeldGap of the cloth
// (vz^2 / 2g <= 1e-7 m, vz at most 1.4 mm/s) never leaves it: the cloth keeps it down and the hop's
// vertical speed goes into the cloth like a landing's (energy is only lost). Left airborne, such a
// ball in a frozen cluster skipped the cloth's held contacts: its touching, pressed neighbours met
// it again and again at one instant (seed7-shot386: vz = 1.4e-7 m/s; seed7-shot11298: a cluster
// struck by a ball on a 0.1 mm hop, the struck ball bouncing 1.2e-7 m and its neighbours thrown up
// by micrometres a second by the laws' friction). As the hold rule takes a micro-bounce on the cloth.
void clothAnswers(AirState& s, double radius, double mass, const PhysicsParams& p, bool& bounced, TableImpactResult& bounce,
                  bool& kept)
{
    const double keep = 2.0 * p.gravity * kHeldGap;  // vz^2 of a hop of kHeldGap
    if (s.z <= kHeightTolerance && s.vz < 0.0) {
        bounced = true;
        bounce = resolveTableImpact(s, radius, mass, p);
        s = bounce.after;
        if (s.vz > 0.0 && s.vz * s.vz <= keep) {
            kept = true;
            s.z = 0.0;
            s.vz = 0.0;
            s.motion = classify(s, radius);
        }
    } else if (s.z <= kHeightTolerance && s.vz > 0.0 && s.vz * s.vz <= keep) {
        kept = true;
        s.z = 0.0;
        s.vz = 0.0;
        s.motion = classify(s, radius);
    }
}

}  // namespace

FixedImpactResult resolveFixedImpact(const AirState& before, double radius, double mass, const Vec3& normal,
                                     double restitution, double friction)
{
    return resolveFixedImpact(before, radius, mass, normal, restitution, friction, nullptr);
}

AirBallBallResult resolveAirBallBall(const AirState& a, double ra, double ma, const AirState& b, double rb, double mb,
                                     const PhysicsParams& p)
{
    return resolveAirBallBall(a, ra, ma, b, rb, mb, p, nullptr);
}

FixedImpactResult resolveFixedImpact(const AirState& before, double radius, double mass, const Vec3& normal,
                                     double restitution, double friction, FixedImpactTrace* trace)
{
    FixedImpactResult r;
    r.after = before;
    const Vec3 v = velocity3(before);
    const double vn = v.dot(normal);
    r.approachSpeed = -vn;
    if (trace) *trace = FixedImpactTrace{v};
    if (vn < 0.0) {
        const double pn = -(1.0 + restitution) * mass * vn;  // N s
        const Vec3 q = -radius * normal;                      // m, the contact from the centre
        const Vec3 contact = v + before.spin.cross(q);
        const Vec3 slip = contact - contact.dot(normal) * normal;
        const double slipSpeed = slip.norm();
        Vec3 pt = Vec3::Zero();
        r.slipEnded = true;
        if (slipSpeed > 0.0) {
            const double stopping = (2.0 / 7.0) * mass * slipSpeed;
            const double limit = std::max(0.0, friction) * pn;
            r.slipEnded = stopping <= limit;
            pt = -(std::min(stopping, limit) / slipSpeed) * slip;
        }
        r.impulse = pn * normal + pt;
        if (trace) {
            trace->normalImpulse = pn;
            trace->contactOffset = q;
            trace->contactVelocity = contact;
            trace->slip = slip;
            trace->stopping = (2.0 / 7.0) * mass * slipSpeed;
            trace->limit = std::max(0.0, friction) * pn;
            trace->tangentialImpulse = pt;
        }
        setVelocity3(r.after, v + r.impulse / mass);
        r.after.spin = before.spin + q.cross(pt) / ballInertia(mass, radius);
    }
    r.after.motion = classify(r.after, radius);
    return r;
}

AirBallBallResult resolveAirBallBall(const AirState& a, double ra, double ma, const AirState& b, double rb, double mb,
                                     const PhysicsParams& p, AirBallBallTrace* trace)
{
    AirBallBallResult r;
    r.a = a;
    r.b = b;
    const Vec3 d = centre3(b, rb) - centre3(a, ra);
    const Vec3 n = d / d.norm();
    r.normal = n;
    const Vec3 va = velocity3(a), vb = velocity3(b);
    r.approachSpeed = (va - vb).dot(n);
    const double invMass = 1.0 / ma + 1.0 / mb;  // 1/kg
    const double pn = std::max(0.0, (1.0 + p.ballBallRestitution) * r.approachSpeed / invMass);  // N s
    Vec3 onA = -pn * n;
    Vec3 tangential = Vec3::Zero();
    if (p.ballBallModel == BallBallModel::Frictional && pn > 0.0) {
        // The contact points' velocities, v + w x (R n) on a and v + w x (-R n) on b; the normal impulse
        // does not change their tangential difference (it acts through both centres along n).
        const Vec3 slipFull = (va + a.spin.cross(ra * n)) - (vb - b.spin.cross(rb * n));
        const Vec3 slip = slipFull - slipFull.dot(n) * n;
        const double slipSpeed = slip.norm();
        if (slipSpeed > 0.0) {
            const double stopping = slipSpeed / (3.5 * invMass);
            const double magnitude = std::min(ballBallFriction(p, slipSpeed) * pn, stopping);
            tangential = -(magnitude / slipSpeed) * slip;
            if (trace) {
                trace->mu = ballBallFriction(p, slipSpeed);
                trace->stopping = stopping;
            }
        }
        if (trace) {
            trace->frictional = true;
            trace->slip = slip;
        }
    }
    onA += tangential;
    r.impulse = onA;
    setVelocity3(r.a, va + onA / ma);
    setVelocity3(r.b, vb - onA / mb);
    r.a.spin += (ra * n).cross(tangential) / ballInertia(ma, ra);
    r.b.spin += (rb * n).cross(tangential) / ballInertia(mb, rb);
    r.a.motion = classify(r.a, ra);
    r.b.motion = classify(r.b, rb);
    bool aKept = false, bKept = false;
    if (trace) {
        trace->va = va;
        trace->vb = vb;
        trace->inverseMass = invMass;
        trace->normalImpulse = pn;
        trace->tangentialImpulse = tangential;
        trace->aLaw = r.a;
        trace->bLaw = r.b;
    }
    clothAnswers(r.a, ra, ma, p, r.aBounced, r.aBounce, aKept);
    clothAnswers(r.b, rb, mb, p, r.bBounced, r.bBounce, bKept);
    if (trace) {
        trace->aKept = aKept;
        trace->bKept = bKept;
    }
    return r;
}

bool airTouchRests(const AirBallBallResult& res, const AirState& a, const AirState& b)
{
    auto unchanged = [](const AirState& x, const AirState& y) {
        return x.velocity == y.velocity && x.vz == y.vz && x.spin == y.spin;
    };
    return res.approachSpeed <= kRestingSpeed && (res.impulse.isZero(0.0) || (unchanged(res.a, a) && unchanged(res.b, b)));
}

}  // namespace cuelab
