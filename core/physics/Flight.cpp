#include "Flight.h"

#include <algorithm>
#include <cmath>

namespace cuelab {

AirState lifted(const BallState& s, double z, double vz)
{
    AirState out = s;
    out.z = z;
    out.vz = vz;
    return out;
}

bool isAirborne(const AirState& s)
{
    return s.z > kHeightTolerance || s.vz > 0.0;
}

SpacePath clothPath(const Path& p, double radius)
{
    return SpacePath{Vec3(p.c0.x(), p.c0.y(), radius), Vec3(p.c1.x(), p.c1.y(), 0.0), Vec3(p.c2.x(), p.c2.y(), 0.0)};
}

SpacePath flightPath(const AirState& s, double radius, double gravity)
{
    return SpacePath{Vec3(s.position.x(), s.position.y(), radius + s.z), Vec3(s.velocity.x(), s.velocity.y(), s.vz),
                     Vec3(0.0, 0.0, -0.5 * gravity)};
}

AirState fly(const AirState& s, double gravity, double dt)
{
    AirState out = s;
    if (dt <= 0.0) return out;
    out.position = s.position + dt * s.velocity;
    out.z = s.z + dt * (s.vz - 0.5 * gravity * dt);
    out.vz = s.vz - gravity * dt;
    return out;
}

double landingSpeed(const AirState& s, double gravity)
{
    return std::sqrt(std::max(0.0, s.vz * s.vz + 2.0 * gravity * std::max(0.0, s.z)));
}

double landingTime(const AirState& s, double gravity)
{
    if (!isAirborne(s)) return 0.0;
    if (!(gravity > 0.0)) return kNever;
    const double z = std::max(0.0, s.z);
    // From the cloth the root is 2 vz / g; written so, it is that number to the last bit.
    if (z == 0.0) return 2.0 * s.vz / gravity;
    // Roots of z + vz t - g t^2 / 2: t = (vz +- w) / g, w = sqrt(vz^2 + 2 g z) >= |vz|. The positive
    // one is (vz + w) / g; when vz < 0 that sum cancels, and the same root is 2 z / (w - vz).
    const double w = landingSpeed(s, gravity);
    return s.vz >= 0.0 ? (s.vz + w) / gravity : 2.0 * z / (w - s.vz);
}

SpacePath heldFlightPath(const AirState& s, double radius, double gravity, const Vec3& push)
{
    SpacePath path = flightPath(s, radius, gravity);
    path.c2 += 0.5 * push;
    return path;
}

double heldLandingTime(const AirState& s, double gravity, const Vec3& push)
{
    return landingTime(s, gravity - push.z());
}

AirState flyHeld(const AirState& s, double gravity, const Vec3& push, double dt)
{
    if (dt <= 0.0) return s;
    const double tl = heldLandingTime(s, gravity, push);
    const double tau = std::min(dt, tl);
    AirState out = fly(s, gravity - push.z(), tau);
    out.position += (0.5 * tau * tau) * push.head<2>();
    out.velocity += tau * push.head<2>();
    if (dt >= tl) out.z = 0.0;
    out.z = std::max(0.0, out.z);
    return out;
}

double apexTime(const AirState& s, double gravity)
{
    if (!(gravity > 0.0)) return s.vz > 0.0 ? kNever : 0.0;
    return s.vz > 0.0 ? s.vz / gravity : 0.0;
}

double apexHeight(const AirState& s, double gravity)
{
    const double z = std::max(0.0, s.z);
    if (s.vz <= 0.0) return z;
    if (!(gravity > 0.0)) return kNever;
    return z + s.vz * s.vz / (2.0 * gravity);
}

double mechanicalEnergy(const AirState& s, double radius, double mass, double gravity)
{
        // kineticEnergy counts the vertical velocity too; the height adds m g z.
    if (isOutOfPlay(s.motion)) return 0.0;
    return kineticEnergy(s, radius, mass) + mass * gravity * s.z;
}

SpaceContact spaceContact(const AirState& a, double ra, const AirState& b, double rb)
{
    SpaceContact c;
    const Vec3 d(b.position.x() - a.position.x(), b.position.y() - a.position.y(), (rb + b.z) - (ra + a.z));
    c.distance = d.norm();
    if (!(c.distance > 0.0)) return c;
    c.normal = d / c.distance;
    c.gap = c.distance - (ra + rb);
    const Vec3 v = velocity3(b) - velocity3(a);
    c.normalSpeed = v.dot(c.normal);
    c.tangentSpeed2 = std::max(0.0, v.squaredNorm() - c.normalSpeed * c.normalSpeed);
    return c;
}

}  // namespace cuelab
