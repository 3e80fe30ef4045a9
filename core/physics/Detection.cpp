#include "Detection.h"

#include "Quartic.h"

#include <array>
#include <cmath>

namespace cuelab {

namespace {

// ---- TEMPORARY: stands in for Quartic.cpp (solveQuartic) until it is committed; deleted then. ----
double evalPoly(const double* c, int degree, double x)
{
    double v = c[0];
    for (int i = 1; i <= degree; ++i) v = v * x + c[i];
    return v;
}
int tempRealRoots(const double* c, int degree, double lo, double hi, double* roots)
{
    while (degree > 0 && c[0] == 0.0) {
        ++c;
        --degree;
    }
    if (degree <= 0) return 0;
    if (degree == 1) {
        const double r = -c[1] / c[0];
        if (r >= lo && r <= hi) {
            roots[0] = r;
            return 1;
        }
        return 0;
    }
    double deriv[4];
    for (int i = 0; i < degree; ++i) deriv[i] = c[i] * static_cast<double>(degree - i);
    double crit[4];
    const int nc = tempRealRoots(deriv, degree - 1, lo, hi, crit);
    double knots[6];
    int nk = 0;
    knots[nk++] = lo;
    for (int i = 0; i < nc; ++i) knots[nk++] = crit[i];
    knots[nk++] = hi;
    int n = 0;
    for (int k = 0; k + 1 < nk; ++k) {
        double a = knots[k], b = knots[k + 1];
        double fa = evalPoly(c, degree, a), fb = evalPoly(c, degree, b);
        if (fa == 0.0) {
            if (n == 0 || roots[n - 1] != a) roots[n++] = a;
            continue;
        }
        if ((fa > 0) == (fb > 0) && fb != 0.0) continue;
        if (fb == 0.0) continue;  // reported as the next piece's left end
        for (int it = 0; it < 200 && b - a > 0; ++it) {
            const double m = 0.5 * (a + b);
            if (m <= a || m >= b) break;
            const double fm = evalPoly(c, degree, m);
            if ((fm > 0) == (fa > 0)) {
                a = m;
                fa = fm;
            } else {
                b = m;
            }
        }
        roots[n++] = 0.5 * (a + b);
    }
    if (nk > 0) {
        const double fh = evalPoly(c, degree, hi);
        if (fh == 0.0 && (n == 0 || roots[n - 1] != hi)) roots[n++] = hi;
    }
    return n;
}
int solveQuarticTemp(const Quartic& c, std::array<double, 4>& roots)
{
    double scale = 0.0;
    for (double x : c) scale = std::max(scale, std::abs(x));
    if (scale == 0.0) return 0;
    // Cauchy bound on the roots' magnitude.
    int lead = 0;
    while (lead < 4 && c[static_cast<std::size_t>(lead)] == 0.0) ++lead;
    double bound = 0.0;
    for (int i = lead + 1; i <= 4; ++i)
        bound = std::max(bound, std::abs(c[static_cast<std::size_t>(i)] / c[static_cast<std::size_t>(lead)]));
    bound += 1.0;
    double r[8];
    const int n = tempRealRoots(c.data(), 4, -bound, bound, r);
    for (int i = 0; i < n && i < 4; ++i) roots[static_cast<std::size_t>(i)] = r[i];
    return std::min(n, 4);
}
// ---- end TEMPORARY ----

// The first root s in (0, H] of f at which f falls (f' < 0): where a gap closes.
double firstFallingRoot(const Quartic& f, double horizon)
{
    std::array<double, 4> roots{};
    const int n = solveQuarticTemp(f, roots);
    for (int i = 0; i < n; ++i) {
        const double s = roots[static_cast<std::size_t>(i)];
        if (s <= 0.0 || s > horizon) continue;
        const double slope = ((4.0 * f[0] * s + 3.0 * f[1]) * s + 2.0 * f[2]) * s + f[3];
        if (slope < 0.0) return s;
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
        // Touching (or overlapping by rounding): a contact now if the gap is closing.
        if (d0.dot(d1) < 0.0) return 0.0;
    }
    return firstFallingRoot(distanceQuartic(d0, d1, d2, reach), horizon);
}

}  // namespace

double ballBallTime(const Path& a, double ra, const Path& b, double rb, double horizon)
{
    return circleContactTime(b.c0 - a.c0, b.c1 - a.c1, b.c2 - a.c2, ra + rb, horizon);
}

double jawTime(const Path& p, double radius, const JawTip& jaw, double horizon)
{
    return circleContactTime(p.c0 - jaw.centre, p.c1, p.c2, radius + jaw.radius, horizon);
}

double pocketTime(const Path& p, const Pocket& pocket, double horizon)
{
    const Vec2 d0 = p.c0 - pocket.centre;
    if (d0.squaredNorm() <= pocket.radius * pocket.radius) return 0.0;
    return firstFallingRoot(distanceQuartic(d0, p.c1, p.c2, pocket.radius), horizon);
}

double cushionTime(const Path& p, double radius, const CushionSegment& seg, double horizon)
{
    // g(s) = (p(s) - a) . N - R = g0 + g1 s + g2 s^2.
    const double g0 = (p.c0 - seg.a).dot(seg.normal) - radius;
    const double g1 = p.c1.dot(seg.normal);
    const double g2 = p.c2.dot(seg.normal);
    const Vec2 along = seg.b - seg.a;
    const double along2 = along.squaredNorm();
    auto onSegment = [&](double s) {
        const double lambda = (p.at(s) - seg.a).dot(along);
        return lambda >= 0.0 && lambda <= along2;
    };
    if (std::abs(g0) <= kContactTolerance && g1 < 0.0 && onSegment(0.0)) return 0.0;

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
