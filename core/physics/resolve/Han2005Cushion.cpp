#include "resolve/Han2005Cushion.h"

#include "Motion.h"

#include <algorithm>
#include <cmath>

namespace cuelab {

CushionResult hanCushion(const BallState& before, const Vec2& normal, double radius, double mass,
                         double noseHeight, double restitution, double friction, HanTrace* trace)
{
    const double R = radius;
    const double sinA = std::clamp(noseHeight / R - 1.0, -1.0, 1.0);
    const double cosA = std::sqrt(1.0 - sinA * sinA);

    // Rail frame: X into the rail (-N), Y = z x X along it.
    const Vec2 X = -normal;
    const Vec2 Y(-X.y(), X.x());
    const double vx = before.velocity.dot(X);
    const double vy = before.velocity.dot(Y);
    const double wx = before.spin.head<2>().dot(X);
    const double wy = before.spin.head<2>().dot(Y);
    const double wz = before.spin.z();

    const double A = 7.0 / (2.0 * mass);  // 1/kg, slip change per unit tangential impulse
    const double B = 1.0 / mass;          // 1/kg, normal velocity change per unit normal impulse
    const double sx = vx * sinA + R * wy;
    const double sy = -vy - R * wz * cosA + R * wx * sinA;
    const double c = -vx * cosA;  // m/s, normal velocity at the contact (< 0 when approaching)
    const double slip = std::hypot(sx, sy);

    const double PzE = std::max(0.0, -(1.0 + restitution) * c / B);  // N s, compression + restitution
    const double PzS = slip / A;                                      // N s, what stops the slip
    double PxE = 0.0, PyE = 0.0;
    if (PzS <= friction * PzE) {
        PxE = sx / A;
        PyE = sy / A;
    } else if (slip > 0.0) {
        PxE = friction * PzE * sx / slip;
        PyE = friction * PzE * sy / slip;
    }
    // From the contact frame back to the rail frame.
    const double PX = -PxE * sinA - PzE * cosA;
    const double PY = PyE;
    const double PZ = PxE * cosA - PzE * sinA;

    const double I = ballInertia(mass, R);
    const double vx1 = vx + PX / mass;
    const double vy1 = vy + PY / mass;
    const double wx1 = wx - (R / I) * PY * sinA;
    const double wy1 = wy + (R / I) * (PX * sinA - PZ * cosA);
    const double wz1 = wz + (R / I) * PY * cosA;

    CushionResult r;
    r.approachSpeed = vx;
    r.after = before;
    r.after.velocity = vx1 * X + vy1 * Y;
    const Vec2 wxy = wx1 * X + wy1 * Y;
    r.after.spin = Vec3(wxy.x(), wxy.y(), wz1);
    r.after.motion = classify(r.after, R);
    const Vec2 planar = PX * X + PY * Y;
    r.impulse = Vec3(planar.x(), planar.y(), PZ);
    if (trace)
        *trace = HanTrace{sinA, cosA, X,   Y,   vx,   vy,   wx, wy, wz, sx,  sy,  slip, c,   A,   B,   PzE,
                          PzS,  PzS <= friction * PzE, PxE, PyE, PX, PY, PZ, vx1, vy1, wx1, wy1, wz1};
    return r;
}

CushionResult han2005Cushion(const CushionContact& c, const PhysicsParams& p)
{
    return hanCushion(c.before, c.normal, c.radius, c.mass, c.noseHeight, p.cushionRestitution, p.cushionFriction);
}

}  // namespace cuelab
