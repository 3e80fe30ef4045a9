#include "Detection.h"

#include "Quartic.h"

#include <algorithm>
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
    // Touching the circle past a tangent point is overlapping the rail nose or the facing there
    // (Table.h): that piece's own detection is the contact, not the tip's.
    const double s = circleContactTime(p.c0 - jaw.centre, p.c1, p.c2, radius + jaw.radius, horizon);
    return s != kNever && onJawArc(jaw, p.at(s), kContactTolerance) ? s : kNever;
}

double pocketTime(const Path& p, const Pocket& pocket, double horizon)
{
    const Vec2 d0 = p.c0 - pocket.centre;
    if (d0.squaredNorm() <= pocket.radius * pocket.radius) return 0.0;
    return firstFallingRoot(pocketGap(p, pocket), horizon);
}

double cushionTime(const Path& p, double radius, const CushionSegment& seg, double horizon)
{
    // g(s) = (p(s) - a) . N - R = g0 + g1 s + g2 s^2, and the foot of the perpendicular
    // f(s) = (p(s) - a) . T = f0 + f1 s + f2 s^2 (m from a along the segment, of length L).
    const Quartic g = cushionGap(p, radius, seg);
    const double g0 = g[4], g1 = g[3], g2 = g[2];
    const Vec2 along = seg.b - seg.a;
    const double L = along.norm();
    const Vec2 tangent = along / L;
    const double f0 = (p.c0 - seg.a).dot(tangent), f1 = p.c1.dot(tangent), f2 = p.c2.dot(tangent);
    // Touching at s: the gap within kContactTolerance and the foot on the segment, up to rounding of
    // where it is (a ball at an end of the segment, the junction with the jaw whose normal is the same
    // there, touches this cushion too; as the held contacts' geometry). A contact then if the ball
    // approaches, or rests against the nose (normal speed below kRestingSpeed) while its acceleration
    // presses it in, or parts so slowly that it comes back before the gap has opened past
    // kContactTolerance (its largest value g + g'^2 / (4 |g2|)): a resting contact too (see
    // circleContactTime).
    auto contactAt = [&](double s) {
        const double gap = g0 + (g1 + g2 * s) * s;
        const double foot = f0 + (f1 + f2 * s) * s;
        if (gap > kContactTolerance || gap < -kSunkTolerance || foot < -kContactTolerance || foot > L + kContactTolerance) return false;
        const double speed = g1 + 2.0 * g2 * s;
        if (speed < -kRestingSpeed || (speed <= kRestingSpeed && g2 < 0.0)) return true;
        return speed > 0.0 && g2 < 0.0 && gap + speed * speed / (-4.0 * g2) <= kContactTolerance;
    };
    if (contactAt(0.0)) return 0.0;

    // Where the gap closes with the foot on the segment.
    double best = kNever;
    std::array<double, 2> roots;
    for (int i = 0, n = solveQuadratic(g2, g1, g0, roots); i < n; ++i) {
        const double s = roots[static_cast<std::size_t>(i)];
        if (s <= 0.0 || s > horizon) continue;
        if (g1 + 2.0 * g2 * s < 0.0 && onCushionSegment(p, seg, s)) {
            best = s;
            break;
        }
    }
    // Where the foot enters the segment through an end with the ball touching the line, closing in:
    // a ball that follows the jaw at the junction (held against it) passes onto the cushion there, and
    // the gap never crosses zero on the segment (it is zero at the end and falls past it).
    for (const double end : {0.0, L}) {
        const double inward = end == 0.0 ? 1.0 : -1.0;
        for (int i = 0, n = solveQuadratic(f2, f1, f0 - end, roots); i < n; ++i) {
            const double s = roots[static_cast<std::size_t>(i)];
            if (s <= 0.0 || s > horizon || s >= best) continue;
            if (inward * (f1 + 2.0 * f2 * s) > 0.0 && contactAt(s)) {
                best = s;
                break;
            }
        }
    }
    return best;
}

}  // namespace cuelab
