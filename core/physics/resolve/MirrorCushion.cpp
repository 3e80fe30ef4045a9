#include "resolve/MirrorCushion.h"

#include "Motion.h"

namespace cuelab {

CushionResult mirrorCushion(const BallState& before, const Vec2& normal, double radius, double mass,
                            double restitution, MirrorTrace* trace)
{
    CushionResult r;
    r.after = before;
    const double vn = before.velocity.dot(normal);
    r.approachSpeed = -vn;
    const Vec2 dv = -(1.0 + restitution) * vn * normal;
    r.after.velocity += dv;
    r.after.motion = classify(r.after, radius);
    r.impulse = Vec3(mass * dv.x(), mass * dv.y(), 0.0);
    if (trace) {
        trace->normalVelocity = vn;
        trace->velocityChange = dv;
    }
    return r;
}

CushionResult mirrorCushion(const CushionContact& c, const PhysicsParams& p)
{
    return mirrorCushion(c.before, c.normal, c.radius, c.mass, p.cushionRestitution);
}

}  // namespace cuelab
