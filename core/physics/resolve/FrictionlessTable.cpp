#include "resolve/FrictionlessTable.h"

namespace cuelab {

TableImpactResult frictionlessTable(const AirState& before, double radius, double mass, double restitution)
{
    TableImpactResult r;
    r.after = before;
    r.after.z = 0.0;
    if (before.vz < 0.0) {
        r.approachSpeed = -before.vz;
        const double pn = (1.0 + restitution) * mass * r.approachSpeed;  // N s, up
        r.after.vz = restitution * r.approachSpeed;
        r.impulse = Vec3(0.0, 0.0, pn);
    }
    r.after.motion = classify(r.after, radius);
    r.slipEnded = slipVelocity(r.after, radius).norm() == 0.0;
    return r;
}

TableImpactResult frictionlessTable(const TableContact& c, const PhysicsParams& p)
{
    return frictionlessTable(c.before, c.radius, c.mass, p.tableRestitution);
}

}  // namespace cuelab
