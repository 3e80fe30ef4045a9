#include "CueImpact.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cuelab {

double squirtAngle(double side, double ballMass, double endMass)
{
    if (!(endMass > 0.0)) return 0.0;
    const double a = std::clamp(side, -1.0, 1.0);
    const double c = 1.0 - a * a;
    return std::atan(2.5 * a * std::sqrt(c) / (1.0 + ballMass / endMass + 2.5 * c));
}

CueImpactResult resolveCueStrike(const BallState& before, double radius, double mass, const CueStrike& strike,
                                 CueImpactTrace* trace)
{
    const double R = radius;
    double a = strike.side * R;    // m, sideways offset of the tip (+ = player's right)
    double b = strike.height * R;  // m, vertical offset (+ = above the centre)
    // The tip must touch the ball: keep (a, b) inside the silhouette.
    const double offset = std::hypot(a, b);
    if (offset > R) {
        a *= R / offset;
        b *= R / offset;
    }
    const double c = std::sqrt(std::max(0.0, R * R - a * a - b * b));

    const double phi = strike.headingDeg * std::numbers::pi / 180.0;
    const double theta = strike.elevationDeg * std::numbers::pi / 180.0;
    const Vec3 d(std::cos(phi), std::sin(phi), 0.0);
    const Vec3 z(0.0, 0.0, 1.0);
    const Vec3 right = d.cross(z);
    const Vec3 e = std::cos(theta) * d - std::sin(theta) * z;  // cue axis, pointing into the ball
    const Vec3 q = a * right + b * z - c * d;                  // contact point relative to the centre

    const double inertia = 0.4 * mass * R * R;
    const double lever2 = q.cross(e).squaredNorm();  // m^2, |Q x e|^2
    const double F = 2.0 * strike.speed / (1.0 / strike.cueMass + 1.0 / mass + lever2 / inertia);  // N s

    CueImpactResult r;
    r.impulse = F * e;
    r.after = before;
    r.after.velocity = before.velocity + (F * std::cos(theta) / mass) * d.head<2>();
    r.after.spin = before.spin + q.cross(r.impulse) / inertia;
    if (strike.endMass > 0.0 && a != 0.0) {
        // Squirt: the ball leaves off the cue line, turned away from the side of the english.
        r.squirt = squirtAngle(a / R, mass, strike.endMass);
        const Vec2 dv = r.after.velocity - before.velocity;
        const double cs = std::cos(r.squirt), sn = std::sin(r.squirt);
        r.after.velocity = before.velocity + Vec2(cs * dv.x() - sn * dv.y(), sn * dv.x() + cs * dv.y());
        const Vec2 planar = r.impulse.head<2>();
        r.impulse.head<2>() = Vec2(cs * planar.x() - sn * planar.y(), sn * planar.x() + cs * planar.y());
    }
    r.after.motion = classify(r.after, R);
    r.contactPoint = before.position + q.head<2>();
    r.heading = d.head<2>();
    if (trace) *trace = CueImpactTrace{a, b, offset > R, c, phi, theta, d, right, e, q, inertia, lever2, F};
    return r;
}

}  // namespace cuelab
