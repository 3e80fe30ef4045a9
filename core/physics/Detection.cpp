#include "Detection.h"

#include "Quartic.h"

#include <cmath>

namespace cuelab {

namespace {

// The first root s in (0, H] of f at which f falls (f' < 0): where a gap closes. A root where f
// rises (the bodies part) or only touches zero (a graze) is passed over; a quartic has at most four.
double firstFallingRoot(const Quartic& f, double horizon)
{
    double lo = 0.0;
    for (int k = 0; k < 4; ++k) {
        const double s = smallestRootInInterval(f, lo, horizon);
        if (s == kNever) return kNever;
        const double slope = ((4.0 * f[0] * s + 3.0 * f[1]) * s + 2.0 * f[2]) * s + f[3];
        if (slope < 0.0) return s;
        lo = s;
    }
    return kNever;
}

// |d0 + d1 s + d2 s^2|^2 - reach^2 as a quartic in s.
Quartic distanceQuartic(const Vec2& d0, const Vec2& d1, const Vec2& d2, double reach)
{
    return {d2.squaredNorm(), 2.0 * d1.dot(d2), d1.squaredNorm() + 2.0 * d0.dot(d2), 2.0 * d0.dot(d1),
            d0.squaredNorm() - reach * reach};
}

// Contact with a circle of radius `reach` around a point moving along d(s) (relative position).
double circleContactTime(const Vec2& d0, const Vec2& d1, const Vec2& d2, double reach, double horizon)
{
    const double dist = d0.norm();
    if (dist - reach <= kContactTolerance) {
        // Touching (or overlapping by rounding): a contact now if the gap is closing, or if it is
        // not opening (normal speed below kRestingSpeed) while the accelerations press the bodies
        // together: |d|^2 then falls from s = 0 on, a double root at 0 no root finder reports.
        const double normalSpeed = d0.dot(d1) / dist;
        if (normalSpeed < -kRestingSpeed) return 0.0;
        const double press = d1.squaredNorm() + 2.0 * d0.dot(d2);  // (|d|^2)'' / 2 at s = 0
        if (normalSpeed <= kRestingSpeed && press < 0.0) return 0.0;
        // Parting so slowly that the accelerations bring the bodies back before the gap has opened
        // past kContactTolerance: |d|'' = (press - vn^2) / |d| < 0, the gap's largest value is
        // gap + vn^2 / (2 |d|''|). That is a resting contact too (a root finder cannot see a gap of
        // 1e-18 m come back down), so the contact is now.
        const double curvature = separationCurvature(d0, d1) + d0.dot(2.0 * d2) / dist;  // |d|'' at s = 0
        if (curvature < 0.0 && (dist - reach) + normalSpeed * normalSpeed / (-2.0 * curvature) <= kContactTolerance)
            return 0.0;
    }
    return firstFallingRoot(distanceQuartic(d0, d1, d2, reach), horizon);
}

}  // namespace

Quartic ballBallGap(const Path& a, double ra, const Path& b, double rb)
{
    return distanceQuartic(b.c0 - a.c0, b.c1 - a.c1, b.c2 - a.c2, touchDistance(ra, rb));
}

Quartic jawGap(const Path& p, double radius, const JawTip& jaw)
{
    return distanceQuartic(p.c0 - jaw.centre, p.c1, p.c2, radius + jaw.radius);
}

Quartic pocketGap(const Path& p, const Pocket& pocket)
{
    return distanceQuartic(p.c0 - pocket.centre, p.c1, p.c2, pocket.radius);
}

Quartic cushionGap(const Path& p, double radius, const CushionSegment& seg)
{
    return {0.0, 0.0, p.c2.dot(seg.normal), p.c1.dot(seg.normal), (p.c0 - seg.a).dot(seg.normal) - radius};
}

bool onCushionSegment(const Path& p, const CushionSegment& seg, double s)
{
    const Vec2 along = seg.b - seg.a;
    const double lambda = (p.at(s) - seg.a).dot(along);
    return lambda >= 0.0 && lambda <= along.squaredNorm();
}

double ballBallTime(const Path& a, double ra, const Path& b, double rb, double horizon)
{
    return circleContactTime(b.c0 - a.c0, b.c1 - a.c1, b.c2 - a.c2, touchDistance(ra, rb), horizon);
}

double jawTime(const Path& p, double radius, const JawTip& jaw, double horizon)
{
    return circleContactTime(p.c0 - jaw.centre, p.c1, p.c2, radius + jaw.radius, horizon);
}

double pocketTime(const Path& p, const Pocket& pocket, double horizon)
{
    const Vec2 d0 = p.c0 - pocket.centre;
    if (d0.squaredNorm() <= pocket.radius * pocket.radius) return 0.0;
    return firstFallingRoot(pocketGap(p, pocket), horizon);
}

double cushionTime(const Path& p, double radius, const CushionSegment& seg, double horizon)
{
    // g(s) = (p(s) - a) . N - R = g0 + g1 s + g2 s^2.
    const Quartic g = cushionGap(p, radius, seg);
    const double g0 = g[4], g1 = g[3], g2 = g[2];
    auto onSegment = [&](double s) { return onCushionSegment(p, seg, s); };
    // Touching: the gap within kContactTolerance and the foot on the segment, up to rounding of where
    // it is (a ball at an end of the segment, the junction with the jaw whose normal is the same there,
    // touches this cushion too, approaching or resting; as the held contacts' geometry).
    auto touchesSegment = [&] {
        const Vec2 along = seg.b - seg.a;
        const double L = along.norm();
        const double foot = (p.c0 - seg.a).dot(along / L);
        return foot >= -kContactTolerance && foot <= L + kContactTolerance;
    };
    if (std::abs(g0) <= kContactTolerance && touchesSegment()) {
        // A contact now if the ball approaches, or rests against the nose (normal speed below
        // kRestingSpeed) while its acceleration presses it in, or parts so slowly that it comes back
        // before the gap has opened past kContactTolerance (its largest value g0 + g1^2 / (4 |g2|)):
        // a resting contact too (see circleContactTime).
        if (g1 < -kRestingSpeed || (g1 <= kRestingSpeed && g2 < 0.0)) return 0.0;
        if (g1 > 0.0 && g2 < 0.0 && g0 + g1 * g1 / (-4.0 * g2) <= kContactTolerance) return 0.0;
    }

    // Roots of the quadratic, stably (no cancellation between -g1 and the square root).
    double roots[2];
    int n = 0;
    if (g2 == 0.0) {
        if (g1 != 0.0) roots[n++] = -g0 / g1;
    } else {
        const double disc = g1 * g1 - 4.0 * g2 * g0;
        if (disc >= 0.0) {
            const double q = -0.5 * (g1 + std::copysign(std::sqrt(disc), g1));
            if (q != 0.0) {
                const double r1 = q / g2, r2 = g0 / q;
                roots[n++] = std::min(r1, r2);
                roots[n++] = std::max(r1, r2);
            } else {
                roots[n++] = 0.0;  // g0 = g1 = 0
            }
        }
    }
    for (int i = 0; i < n; ++i) {
        const double s = roots[i];
        if (s <= 0.0 || s > horizon) continue;
        if (g1 + 2.0 * g2 * s < 0.0 && onSegment(s)) return s;
    }
    return kNever;
}

}  // namespace cuelab
