#include "resolve/Mathavan2010Cushion.h"

#include "Motion.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace cuelab {

namespace {

struct Body {
    Vec3 v;  // m/s, the centre's velocity (v.z() stays 0: the cloth holds the ball)
    Vec3 w;  // rad/s
};

// The tangential part of the velocity of the material point at `r` (from the centre), for a contact
// whose normal is `n`.
Vec3 slipAt(const Body& b, const Vec3& r, const Vec3& n)
{
    const Vec3 u = b.v + b.w.cross(r);
    return u - u.dot(n) * n;
}

}  // namespace

CushionResult mathavan2010Cushion(const CushionContact& c, const PhysicsParams& p)
{
    const double R = c.radius;
    const double m = c.mass;
    const double inertia = ballInertia(m, R);
    const double e = p.cushionRestitution;
    const double muW = p.cushionFriction;  // ball-cushion
    const double muS = p.muSlide;          // ball-cloth
    const double sinT = std::clamp(c.noseHeight / R - 1.0, -1.0, 1.0);
    const double cosT = std::sqrt(1.0 - sinT * sinT);

    const Vec3 X(-c.normal.x(), -c.normal.y(), 0.0);  // into the rail
    const Vec3 z(0.0, 0.0, 1.0);
    const Vec3 rI = R * (cosT * X + sinT * z);  // cushion contact, from the centre
    const Vec3 nI = -rI / R;                    // its normal force on the ball, unit
    const Vec3 rC = -R * z;                     // cloth contact

    CushionResult result;
    result.after = c.before;
    const double vInto = c.before.velocity.dot(-c.normal);  // m/s, the centre towards the rail
    result.approachSpeed = vInto;
    const double approach0 = vInto * cosT;  // m/s, the contact I towards the cushion (z'_I)
    if (!(approach0 > 0.0)) return result;

    Body b{Vec3(c.before.velocity.x(), c.before.velocity.y(), 0.0), c.before.spin};
    const double steps = std::max(1.0, p.mathavanSteps);
    const double dP0 = (1.0 + e) * m * vInto / (steps * cosT);  // N s, the paper's step
    const long long maxSteps = static_cast<long long>(8.0 * steps) + 8;

    // One step of normal impulse dP at I with the directions of the step's start. Returns the
    // cushion's impulse on the ball (the cloth's is applied but not returned).
    const auto step = [&](Body& s, double dP) -> Vec3 {
        const Vec3 slipI = slipAt(s, rI, nI);
        const Vec3 slipC = slipAt(s, rC, z);
        // A friction impulse f at a contact changes that contact's slip by f (1/m + R^2/I) = f 7/(2m).
        const double stopGain = 3.5 / m;
        Vec3 jI = dP * nI;
        const double sI = slipI.norm();
        if (sI > 0.0) jI -= std::min(muW * dP, sI / stopGain) * (slipI / sI);
        const double normalC = std::max(0.0, -jI.z());  // N s, what keeps the ball on the cloth
        Vec3 jC = normalC * z;
        const double sC = slipC.norm();
        if (sC > 0.0) jC -= std::min(muS * normalC, sC / stopGain) * (slipC / sC);
        s.v += (jI + jC) / m;
        s.v.z() = 0.0;  // the cloth takes what is left of the vertical impulse
        s.w += (rI.cross(jI) + rC.cross(jC)) / inertia;
        return jI;
    };
    const auto approach = [&](const Body& s) { return s.v.dot(X) * cosT; };  // z'_I, m/s

    Vec3 impulse = Vec3::Zero();
    double workCompression = 0.0;  // J, work of the normal force while I approaches
    long long n = 0;
    // Compression: until z'_I reaches 0.
    for (; n < maxSteps; ++n) {
        const double z0 = approach(b);
        if (!(z0 > 0.0)) break;
        Body trial = b;
        const Vec3 j = step(trial, dP0);
        const double z1 = approach(trial);
        if (z1 > 0.0) {
            b = trial;
            impulse += j;
            workCompression += dP0 * (z0 + z1) / 2.0;
            continue;
        }
        const double dP = dP0 * z0 / (z0 - z1);  // z' is linear in dP within a step
        impulse += step(b, dP);
        workCompression += dP * z0 / 2.0;
        ++n;
        break;
    }
    // Restitution: until the returned work reaches e^2 of the work of compression.
    double remaining = e * e * workCompression;  // J
    for (; n < maxSteps && remaining > 0.0; ++n) {
        const double z0 = approach(b);  // <= 0 now
        Body trial = b;
        const Vec3 j = step(trial, dP0);
        const double z1 = approach(trial);
        const double work = -dP0 * (z0 + z1) / 2.0;
        if (work < remaining) {
            b = trial;
            impulse += j;
            remaining -= work;
            continue;
        }
        // Returned work over a step dP: -z0 dP - (k/2) dP^2 with k = (z1 - z0)/dP0; cut where it
        // equals `remaining` (the root in (0, dP0], in a form free of cancellation).
        const double a = -(z1 - z0) / (2.0 * dP0);
        const double bq = -z0;
        const double disc = std::max(0.0, bq * bq + 4.0 * a * remaining);
        const double dP = std::clamp(2.0 * remaining / (bq + std::sqrt(disc)), 0.0, dP0);
        impulse += step(b, dP);
        remaining = 0.0;
        break;
    }
    // Guard: a ball still pressing into the cushion keeps no normal velocity into it.
    const double into = b.v.dot(X);
    if (into > 0.0) {
        impulse -= m * into * X;
        b.v -= into * X;
    }

    result.after.velocity = b.v.head<2>();
    result.after.spin = b.w;
    result.after.motion = classify(result.after, R);
    result.impulse = impulse;
    return result;
}

}  // namespace cuelab
