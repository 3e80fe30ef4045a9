#include "AirHoldForce.h"

#include "Contact.h"
#include "Flight.h"
#include "Motion.h"

#include <cmath>

namespace cuelab {

AirHoldForce airHoldForce(const BallState& sa, double ra, double ma, const BallState& sb, double rb, double mb,
                          const PhysicsParams& p)
{
    AirHoldForce f;
    const double g = p.gravity;
    const SpaceContact sc = spaceContact(sb, rb, sa, ra);  // (n from b to a)
    if (!(sc.distance > 0.0)) return f;
    const Vec3& n = sc.normal;
    f.normal = n;
    f.gap = sc.gap;
    f.normalSpeed = sc.normalSpeed;
    const Vec2 nh = n.head<2>();
    const double nh2 = nh.squaredNorm(), nhLength = std::sqrt(nh2);
    const double curvature = kHeldCurvatureShare * sc.tangentSpeed2 / sc.distance;
    f.curvature = curvature;
    double c = 0.0;
    Vec2 friction = Vec2::Zero();  // b's cloth friction along its frozen direction (m/s^2)
    f.labelB = sb.motion;
    const bool fromRest = !(sb.motion == MotionState::Sliding || (sb.motion == MotionState::Rolling && sb.velocity.norm() > kRollOffSpeed));
    f.fromRest = fromRest;
    if (sb.motion == MotionState::Sliding) {
        c = 1.0;
        const Vec2 u = slipVelocity(sb, rb);
        if (u.norm() > 0.0) friction = -(p.muSlide * g) * u.normalized();
    } else if (!fromRest) {
        c = 5.0 / 7.0;
        friction = -(p.muRoll * g) * sb.velocity.normalized();
    } else if (nhLength > 0.0) {
        // At rest it rolls off along the push -n_h, its rolling resistance against it.
        c = 5.0 / 7.0;
        friction = (p.muRoll * g / nhLength) * nh;
        f.labelB = MotionState::Rolling;
    }
    f.response = c;
    f.friction = friction;
    double N = (g * n.z() + nh.dot(friction) - curvature) / (1.0 / ma + c * nh2 / mb);
    if (fromRest && !(c * N * nhLength / mb > p.muRoll * g)) {
        // The push does not beat the rolling resistance: the cloth holds b still.
        f.stillB = true;
        f.labelB = sb.motion;
        N = (g * n.z() - curvature) * ma;
    }
    f.force = N;
    if (!(N > 0.0)) return f;
    f.pushA = (N / ma) * n;
    if (!f.stillB) f.pushB = -(N / mb) * nh;
    return f;
}

AirHoldStart startAirHold(BallState sa, double ra, double ma, BallState sb, double rb, double mb, const PhysicsParams& p)
{
    AirHoldStart out;
    // A slip that has as good as ended, or one that the cloth would end within kSlipRollOutLength, has a
    // direction of rounding, and so would the friction the force is solved with: the re-seat's
    // impulse of a micronewton-second can turn it about and the force's sign with it (seed12-shot78694:
    // 0.29 N, then -0.018 N, and the contact met again at the same instant). It rolls out, as a held
    // group's member does (HeldContacts.cpp), at the hold's event too (an air event's momentum is the
    // cloth's as well as the pair's: AirImpacts.h), and again after the re-seat.
    rollOutRounding(sb, rb, p);
    AirHoldForce f = airHoldForce(sa, ra, ma, sb, rb, mb, p);
    out.entering = f;
    out.force = f;
    out.a = sa;
    out.b = sb;
    if (!(f.force > 0.0) || std::abs(f.gap) > kHeldGap || std::abs(f.normalSpeed) > kHoldSpeed) return out;
    if (f.normalSpeed != 0.0) {
        // Re-seated, as the cloth's held contacts are: the frozen normal of the last segment left the
        // pair parting at about (1 - share) |v_t|^2 s / d (the force would do work on that parting),
        // or approaching when the tangential motion slowed over it (the pair would sink into each
        // other). An impulse along the normal takes it away (inelastic: the energy falls), b
        // answering by Contact.h's rule (the cloth takes the rest).
        const Vec3 n = f.normal;
        const Vec2 nh = n.head<2>();
        const double c = contactResponse(sb);
        const double J = f.normalSpeed / (1.0 / ma + c * nh.squaredNorm() / mb);
        const Vec3 dv = -(J / ma) * n;
        sa.velocity += dv.head<2>();
        sa.vz += dv.z();
        applyContactImpulse(sb, rb, mb, J * nh);
        rollOutRounding(sb, rb, p);
        out.reseated = true;
        out.reseat = J;
        out.reseatResponse = c;
        f = airHoldForce(sa, ra, ma, sb, rb, mb, p);
        out.force = f;
        out.a = sa;
        out.b = sb;
        if (!(f.force > 0.0)) return out;
    }
    // The cloth holds b still: a b rolling slower than kRollOffSpeed (a law's or a re-seat's impulse
    // of rounding, counted as at rest by the force above) is at rest, as a resting touch leaves it
    // (AirCollisions.cpp). Left rolling, its stop nanoseconds later ended the hold, and the pair was
    // met and held again at once until the event cap (wide-seed18-shot123395: 1e-11 m/s, an event
    // every 30 ns).
    if (f.stillB && sb.motion == MotionState::Rolling && sb.velocity.norm() <= kRollOffSpeed) {
        sb.velocity = Vec2::Zero();
        sb.spin.x() = 0.0;
        sb.spin.y() = 0.0;
        sb.motion = classify(sb, rb);
        out.b = sb;
        out.force.labelB = sb.motion;
    }
    out.held = true;
    return out;
}

}  // namespace cuelab
