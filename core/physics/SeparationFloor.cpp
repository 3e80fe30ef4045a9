#include "SeparationFloor.h"

#include "Detection.h"

namespace cuelab {

double enforceSeparation(BallBallResult& r, double massA, double massB)
{
    const double separation = (r.b.velocity - r.a.velocity).dot(r.normal);
    if (separation >= kMinSeparationSpeed) return 0.0;
    const double extra = (kMinSeparationSpeed - separation) / (1.0 / massA + 1.0 / massB);  // N s
    r.a.velocity -= (extra / massA) * r.normal;
    r.b.velocity += (extra / massB) * r.normal;
    r.impulse.head<2>() -= extra * r.normal;
    return extra;
}

double enforceSeparation(CushionResult& r, const Vec2& normal, double mass)
{
    const double separation = r.after.velocity.dot(normal);
    if (separation >= kMinSeparationSpeed) return 0.0;
    const double extra = kMinSeparationSpeed - separation;  // m/s
    r.after.velocity += extra * normal;
    r.impulse.head<2>() += (mass * extra) * normal;
    return mass * extra;
}

}  // namespace cuelab
