#pragma once
// The reference the quartic tests measure the solver against: polynomials built from known roots and
// roots polished by Newton's method, both in binary128 (__float128), and the accuracy promised for a
// simple root (tst_quartic, tst_contactquartic).

#include "Quartic.h"

#include <QList>
#include <QString>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace cuelab::quartictest {

__extension__ typedef __float128 Quad;

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

inline Quad absolute(Quad x) { return x < 0 ? -x : x; }

// Coefficients highest degree first, in binary128.
using QuadPoly = std::array<Quad, 5>;

// The monic-times-scale polynomial with the given real roots and complex pairs alpha +- i beta
// (pairs as alpha, beta, alpha, beta, ...), four roots in all, computed in binary128.
inline QuadPoly polyFromRoots(const QList<double>& realRoots, const QList<double>& pairs, double scale)
{
    QuadPoly p{0, 0, 0, 0, scale};  // degree grows leftwards: p[4 - k .. 4] holds a degree-k poly
    auto multiply = [&p](Quad b, Quad c) {  // p *= (t^2 + b t + c); b, c may describe a linear factor
        QuadPoly next{};
        for (int i = 0; i < 5; ++i) {
            next[i] = c * p[i];
            if (i + 1 < 5) next[i] += b * p[i + 1];
            if (i + 2 < 5) next[i] += p[i + 2];
        }
        p = next;
    };
    for (double r : realRoots) {  // (t - r): shift by one degree, then subtract r p
        QuadPoly next{};
        for (int i = 0; i < 5; ++i) next[i] = (i + 1 < 5 ? p[i + 1] : Quad(0)) - Quad(r) * p[i];
        p = next;
    }
    for (qsizetype i = 0; i + 1 < pairs.size(); i += 2) {
        const Quad alpha = pairs[i];
        const Quad beta = pairs[i + 1];
        multiply(-2 * alpha, alpha * alpha + beta * beta);
    }
    return p;
}

inline Quartic rounded(const QuadPoly& p)
{
    Quartic c{};
    for (int i = 0; i < 5; ++i) c[i] = static_cast<double>(p[i]);
    return c;
}

inline bool representedExactly(const QuadPoly& p)
{
    for (int i = 0; i < 5; ++i)
        if (Quad(static_cast<double>(p[i])) != p[i]) return false;
    return true;
}

struct QuadValue {
    Quad f = 0;
    Quad df = 0;
};

inline QuadValue evaluate(const Quartic& c, Quad x)
{
    QuadValue v{c[0], 0};
    for (int i = 1; i < 5; ++i) {
        v.df = v.df * x + v.f;
        v.f = v.f * x + c[i];
    }
    return v;
}

// The root of the double polynomial c next to x, by Newton's method in binary128. Converges
// quadratically to a simple root, linearly to a multiple one (hence the generous iteration count).
inline double polish(const Quartic& c, double start)
{
    Quad x = start;
    for (int iteration = 0; iteration < 400; ++iteration) {
        const QuadValue v = evaluate(c, x);
        if (v.df == 0) break;
        const Quad step = v.f / v.df;
        x -= step;
        if (absolute(step) <= Quad(1e-33) * absolute(x)) break;
    }
    return static_cast<double>(x);
}

// The accuracy promised for a simple root r of c. Plain evaluation of p near r rounds to a few eps
// sum |c_i| |r|^i, which moves the computed root by that over |p'(r)| (its condition); where that
// would exceed 1e-13 relative, as next to a close pair of roots, the solver evaluates p with twice
// the precision, leaving about eps^2 sum |c_i| |r|^i / |p'(r)|. So: the smaller of the plain bound
// and 1e-12 relative, plus the compensated bound and the rounding of r itself.
inline double simpleRootTolerance(const Quartic& c, double r)
{
    double magnitude = 0.0;
    for (int i = 0; i < 5; ++i) magnitude = magnitude * std::abs(r) + std::abs(c[i]);
    const double slope = std::abs(static_cast<double>(evaluate(c, r).df));
    const double plain = 64.0 * kEpsilon * magnitude / slope;
    const double compensated = 64.0 * kEpsilon * kEpsilon * magnitude / slope;
    return std::min(plain, 1e-12 * std::abs(r)) + compensated + 4.0 * kEpsilon * std::abs(r);
}

inline QString describe(const Quartic& c)
{
    return QString::asprintf("c = {%.17g, %.17g, %.17g, %.17g, %.17g}", c[0], c[1], c[2], c[3], c[4]);
}

// The smallest value in sorted `roots` with lo < r <= hi, +infinity if none.
inline double smallestIn(const std::vector<double>& roots, double lo, double hi)
{
    for (double r : roots)
        if (r > lo && r <= hi) return r;
    return kInfinity;
}

inline bool within(double x, double reference, double relTol)
{
    if (std::isinf(reference) || std::isinf(x)) return x == reference;
    return std::abs(x - reference) <= relTol * std::abs(reference);
}

}  // namespace cuelab::quartictest
