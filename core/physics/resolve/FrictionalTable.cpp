#include "resolve/FrictionalTable.h"

#include <algorithm>

namespace cuelab {

// The contact is the point Q = -R z below the centre. The cloth gives it an impulse P = Pt + Pn z
// (Pt horizontal). The centre's velocity changes by P / m, the spin by Q x P / I = -R (z x Pt) / I
// (the normal part passes through the centre), with I = 2/5 m R^2. The contact point's horizontal
// velocity, the slip u = v + w x Q = (vx - R wy, vy + R wx), changes by
//     du = Pt / m + dw x Q = Pt / m + (R^2 / I) (z x Pt) x z = Pt / m + R^2 Pt / I = (7 / 2) Pt / m,
// along Pt: friction turns neither the slip's direction nor the normal speed. So
//   - normal: Pn = (1 + e) m |vz|, the ball leaves at e |vz|;
//   - tangential: Pt = -(2/7) m u ends the slip; Coulomb allows at most mu Pn; the smaller is applied,
//     against u. Pt . (u + u') / 2 <= 0 is its work: friction only removes energy.
// The spin about z is untouched (the horizontal impulse at Q has no moment about the vertical axis
// through the centre). This is pooltool's frictional_inelastic law without its minimum bounce height.
TableImpactResult frictionalTable(const AirState& before, double radius, double mass, double restitution,
                                  double friction, FrictionalTableTrace* trace)
{
    TableImpactResult r;
    r.after = before;
    r.after.z = 0.0;
    FrictionalTableTrace t;
    if (before.vz < 0.0) {
        r.approachSpeed = -before.vz;
        t.normalImpulse = (1.0 + restitution) * mass * r.approachSpeed;
        r.after.vz = restitution * r.approachSpeed;
        t.slip = slipVelocity(before, radius);
        const double slip = t.slip.norm();
        t.stoppingImpulse = (2.0 / 7.0) * mass * slip;
        t.coulombLimit = std::max(0.0, friction) * t.normalImpulse;
        if (slip > 0.0) {
            r.slipEnded = t.stoppingImpulse <= t.coulombLimit;
            t.frictionImpulse = r.slipEnded ? Vec2(-(2.0 / 7.0) * mass * t.slip)
                                            : Vec2(-(t.coulombLimit / slip) * t.slip);
            const Vec2 dv = t.frictionImpulse / mass;
            r.after.velocity += dv;
            // dw = -R (z x Pt) / I = -(5 / (2 R)) (z x dv), z x dv = (-dv.y, dv.x).
            const double k = 2.5 / radius;
            r.after.spin.x() += k * dv.y();
            r.after.spin.y() -= k * dv.x();
            if (r.slipEnded) {
                // Exactly rolling at the contact: the spin follows the velocity (u = 0).
                r.after.spin.x() = -r.after.velocity.y() / radius;
                r.after.spin.y() = r.after.velocity.x() / radius;
            }
        } else {
            r.slipEnded = true;
        }
        r.impulse = Vec3(t.frictionImpulse.x(), t.frictionImpulse.y(), t.normalImpulse);
    }
    r.after.motion = classify(r.after, radius);
    if (trace) *trace = t;
    return r;
}

TableImpactResult frictionalTable(const TableContact& c, const PhysicsParams& p)
{
    return frictionalTable(c.before, c.radius, c.mass, p.tableRestitution, p.tableFriction);
}

}  // namespace cuelab
