// Real roots of polynomials up to degree four by recursive bracketing on the critical points.
//
// Method. Between two consecutive real roots of p' (the critical points of p), p is monotone, so it
// has at most one root there, and it has one exactly when p changes sign between the two ends. The
// critical points are the roots of p', found the same way from the roots of p'', which come from the
// closed-form quadratic. Each bracketed root is then found by Halley's method safeguarded by
// bisection, started from the quadratic Taylor model at a critical end point, which is already close
// for near-double roots (where an unguided iteration crawls). This is the derivative sequence of
// Collins & Loos (real root isolation, 1976); bracketing the smallest root between critical points
// and a Cauchy bound is the alternative PHYSICS.md gives to Orellana & De Michele (ACM TOMS
// Algorithm 1010, 2020). The walk runs from lo upwards and computes critical points only as far as
// it has to, so the event-detection question "the first root after lo" costs only what precedes it.
//
// Close roots. Next to a close pair of roots |p| is tiny and plain evaluation returns rounding noise
// there, which limits a root r to about eps sum |c_i| |r|^i / |p'(r)|. Where that would exceed 1e-13
// relative, and at critical points whose value is within rounding, p is evaluated again with the
// compensated Horner scheme (twice the precision): the roots of the given coefficients are then
// resolved even for pairs 1e-12 apart.
//
// Tangential roots. A double root (a grazing contact) is a critical point where p vanishes; rounding
// makes the computed value a tiny number of either sign. Where the sign shows no crossing but the
// value is within the forward error bound of its evaluation (Higham, Accuracy and Stability of
// Numerical Algorithms, 2nd ed., 5.1: the error of Horner's rule at x is at most
// gamma_2n sum |c_i| |x|^i), the critical point is taken as a root. So a double root is never lost to
// a rounding error of the wrong sign, and a root within rounding of lo counts as lying at lo, which is
// excluded.

#include "Quartic.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cuelab {

namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A computed |p(x)| at or below this many units of eps times sum |c_i| |x|^i counts as zero. The
// evaluation's own bound is a few eps for degree <= 4; the margin absorbs a few ulps of error in the
// coefficients themselves, which a caller computes from positions and velocities. A grazing miss by
// less than this (about 1e-14 of the squared contact distance) is reported as a touch.
constexpr double kZeroTolerance = 16.0 * kEpsilon;

// Leading coefficients at or below this fraction of sum |c_i| / 8 (between 1/8 and 5/8 of the largest
// coefficient) are dropped: the roots they carry lie beyond about 2^200 (1e60), and evaluating near
// them would overflow.
constexpr double kNegligibleLeading = 0x1p-200;

// The iteration stops once its estimated error is this small relative to the root: a further step
// would be lost in the rounding of the evaluation.
constexpr double kRootTolerance = kEpsilon;

// The Halley error estimate is trusted only once the step is below this fraction of the iterate.
constexpr double kTrustedStep = 1e-4;

// Roots whose attainable accuracy with plain evaluation is worse than this (relative) are refined
// with compensated evaluation.
constexpr double kConditionLimit = 1e-13;

// Safeguarded Halley converges in a handful of steps. Bisection alone halves the bracket, which spans
// at most 2^202 (the root bound below), down to adjacent doubles: some 1100 steps across every binade
// to the smallest subnormal. The cap only guarantees termination on inputs that defeat both.
constexpr int kMaxIterations = 2200;

// p(x) for a polynomial of degree D (coefficients a[0..D], highest first) by Estrin's splitting on
// x2 = x^2. Its error bound is that of Horner's rule up to a small constant (Higham, 5.1 and 5.6),
// but its chain of dependent operations is about half as long, and that chain bounds the speed here.
template <int D>
double estrin(const double* a, double x, double x2)
{
    if constexpr (D == 0)
        return a[0];
    else if constexpr (D == 1)
        return a[0] * x + a[1];
    else if constexpr (D == 2)
        return a[0] * x2 + (a[1] * x + a[2]);
    else if constexpr (D == 3)
        return (a[0] * x + a[1]) * x2 + (a[2] * x + a[3]);
    else if constexpr (D == 4)
        return (a[0] * x2 + (a[1] * x + a[2])) * x2 + (a[3] * x + a[4]);
    else  // (degrees 5 to 8: Horner's rule, Higham 5.1)
        return estrin<D - 1>(a, x, x2) * x + a[D];
}

// A polynomial of degree N (3 to 8) and its Taylor coefficient polynomials d1 = p', d2 = p'' / 2 and
// d3 = p''' / 6, so that p(x + h) = p(x) + d1(x) h + d2(x) h^2 + d3(x) h^3 + ...
template <int N>
struct Expansion {
    double c[N + 1];
    double absC[N + 1];  // |c_i|, for magnitude()
    double d1[N];
    double d2[N - 1];
    double d3[N - 2];

    explicit Expansion(const double* coefficients)
    {
        for (int i = 0; i <= N; ++i) {
            c[i] = coefficients[i];
            absC[i] = std::abs(c[i]);
        }
        for (int i = 0; i < N; ++i) d1[i] = c[i] * (N - i);
        for (int i = 0; i < N - 1; ++i) d2[i] = c[i] * ((N - i) * (N - i - 1) / 2);
        for (int i = 0; i < N - 2; ++i) d3[i] = c[i] * ((N - i) * (N - i - 1) * (N - i - 2) / 6);
    }

    double value(double x) const { return estrin<N>(c, x, x * x); }

    // sum |c_i| |x|^i: the rounding error of value(x) is at most a few eps times this.
    double magnitude(double x) const { return estrin<N>(absC, std::abs(x), x * x); }

    // Whether a computed value f = p(x) is indistinguishable from zero: within the rounding error of
    // its evaluation, bounded by kZeroTolerance sum |c_i| |x|^i.
    bool negligible(double f, double x) const { return std::abs(f) <= kZeroTolerance * magnitude(x); }

    // p(x) as accurately as if computed in twice the working precision and then rounded: the
    // compensated Horner scheme of Graillat, Langlois & Louvet ("Compensated Horner Scheme", 2005),
    // which carries the exact rounding errors of every product and sum (Dekker's TwoProduct with
    // Veltkamp's splitting, Knuth's TwoSum) through a second Horner recurrence. Its error is about
    // eps |p(x)| + eps^2 sum |c_i| |x|^i, so it resolves the sign of p next to close roots, where
    // value() returns rounding noise. Six times the work of value(); used only there.
    double valueCompensated(double x) const
    {
        constexpr double kSplitter = 134217729.0;  // 2^27 + 1
        const double xSplit = kSplitter * x;
        const double xHigh = xSplit - (xSplit - x);
        const double xLow = x - xHigh;
        double s = c[0];
        double correction = 0.0;
        for (int i = 1; i <= N; ++i) {
            const double product = s * x;
            const double sSplit = kSplitter * s;
            const double sHigh = sSplit - (sSplit - s);
            const double sLow = s - sHigh;
            const double productError = sLow * xLow - (((product - sHigh * xHigh) - sLow * xHigh) - sHigh * xLow);
            const double sum = product + c[i];
            const double z = sum - product;
            const double sumError = (product - (sum - z)) + (c[i] - z);
            s = sum;
            correction = correction * x + (productError + sumError);
        }
        return s + correction;
    }
};

// A starting point inside (a, b) for the root of p there. At a critical end point e the Taylor
// model p(e) + p''(e) (x - e)^2 / 2 gives the root to second order, which is what makes near-double
// roots cheap; without one, the secant through the ends (regula falsi) is used.
template <int N>
double startingPoint(const Expansion<N>& p, double a, double fa, bool aCritical, double b, double fb,
                     bool bCritical)
{
    const bool fromA = aCritical && (!bCritical || std::abs(fa) <= std::abs(fb));
    if (fromA || bCritical) {
        const double e = fromA ? a : b;
        const double fe = fromA ? fa : fb;
        const double halfCurvature = estrin<N - 2>(p.d2, e, e * e);
        const double offset = std::sqrt(std::abs(fe / halfCurvature));
        const double x = fromA ? e + offset : e - offset;
        if (x > a && x < b) return x;  // false for NaN (curvature 0) or a model that overshoots
    }
    const double x = a + (b - a) * (fa / (fa - fb));
    return (x > a && x < b) ? x : a + 0.5 * (b - a);
}

// The root of p in (a, b) from x, given p(a) and p(b) of opposite signs and p monotone on [a, b].
// Halley's method, step s = p p' / (p'^2 - p p'' / 2), which converges cubically, safeguarded by
// bisection when a step would leave the bracket or is not below half the step before (the rtsafe
// safeguard of Press et al., Numerical Recipes, 3rd ed., 9.4). It stops when the error left after the
// step just taken, estimated by Halley's error recursion e' = (A^2 - B) e^3 with A = p'' / (2 p') and
// B = p''' / (6 p') (Traub, Iterative Methods for the Solution of Equations, 1964, 8.3), is below the
// rounding of x; that saves a last, merely confirming, evaluation. Compensated: p itself is evaluated
// by valueCompensated(), for roots whose accuracy value()'s rounding would limit; illConditioned
// tells whether that is so at the last iterate.
template <int N, bool Compensated = false>
double rootInBracket(const Expansion<N>& p, double a, double fa, double b, double x, bool& illConditioned)
{
    const bool rising = fa < 0.0;
    double stepBefore = b - a;
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        const double x2 = x * x;
        const double f = Compensated ? p.valueCompensated(x) : estrin<N>(p.c, x, x2);
        const double d1 = estrin<N - 1>(p.d1, x, x2);
        const double d2 = estrin<N - 2>(p.d2, x, x2);
        // Off the critical path of the iteration: whether rounding in value() limits the root to
        // worse than kConditionLimit relative accuracy. That error is about eps sum |c_i| |x|^i /
        // |p'(x)| (the root's condition number), large next to a close pair of roots.
        illConditioned = kEpsilon * estrin<N>(p.absC, std::abs(x), x2) > kConditionLimit * std::abs(x * d1);
        if (f == 0.0) return x;
        if ((f < 0.0) == rising)
            a = x;
        else
            b = x;
        const double step = f * d1 / (d1 * d1 - f * d2);
        const double next = x - step;
        if (next > a && next < b && std::abs(2.0 * step) <= std::abs(stepBefore)) {
            const double d3 = estrin<N - 3>(p.d3, x, x2);
            const double errorTimesSlope2 = std::abs(d2 * d2 - d1 * d3) * std::abs(step * step * step);
            x = next;
            stepBefore = step;
            // The estimate is asymptotic: far from the root, or where A^2 - B happens to cancel, it
            // can be much too small. Trusting it only after a small step bounds that damage to about
            // kTrustedStep^3 relative for a well-conditioned root.
            const bool smallStep = std::abs(step) <= kTrustedStep * std::abs(x);
            if (smallStep && errorTimesSlope2 <= kRootTolerance * std::abs(x) * (d1 * d1)) return x;
        } else {
            stepBefore = 0.5 * (b - a);
            x = a + stepBefore;
            if (x == a || x == b) return x;  // the bracket is two adjacent doubles
        }
    }
    return x;
}

// The real roots of a polynomial of degree N in (lo, hi], one at a time in ascending order. next()
// finds the next one lazily: asking only for the first root costs only the critical points before it.
// The critical points come from a Walker over the derivative. Requires lo < hi, both finite, and a
// nonzero leading coefficient. A root of multiplicity two or more comes out once or, when rounding
// splits it, as two nearly equal values.
template <int N>
class Walker {
public:
    Walker(const double* c, double lo, double hi)
        : p_(c), derivative_(p_.d1, lo, hi), hi_(hi), a_(lo), fa_(p_.value(lo))
    {
    }

    bool next(double& root)
    {
        while (!done_) {
            double b = hi_;
            const bool bCritical = derivative_.next(b) && b < hi_;
            if (!bCritical) {
                done_ = true;
                b = hi_;
            }
            double fb = p_.value(b);
            if (bCritical && p_.negligible(fb, b)) {
                // The sign of p at a critical point tells a close pair of roots from none; only the
                // compensated value resolves it when the plain one is rounding noise.
                fb = p_.valueCompensated(b);
            }
            const double a = a_;
            const double fa = fa_;
            const bool aCritical = aCritical_;
            const bool aIsLo = aIsLo_;
            a_ = b;
            fa_ = fb;
            aCritical_ = bCritical;
            aIsLo_ = false;
            // A value at lo that is zero within rounding is a root at lo, excluded.
            const auto aIsRoot = [&] { return fa == 0.0 || (aIsLo && p_.negligible(fa, a)); };
            if (((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0)) && !aIsRoot()) {
                const double start = startingPoint<N>(p_, a, fa, aCritical, b, fb, bCritical);
                bool illConditioned = false;
                root = rootInBracket<N>(p_, a, fa, b, start, illConditioned);
                if (illConditioned) root = rootInBracket<N, true>(p_, a, fa, b, root, illConditioned);
                return true;
            }
            // No sign change: p at b is either clear of zero or a (tangential) root within rounding.
            // Only here is a tiny value snapped to zero; a tiny value of the crossing sign was taken
            // at its word above, so that a resolvable pair of close roots yields both. A root at a
            // already stands for p on the monotone piece up to b, which stays within rounding of
            // zero: b is no further root (a double root is reported once, also when a search starts
            // from it, and the search from the first of a close pair goes on to the second).
            if ((fb == 0.0 || p_.negligible(fb, b)) && !aIsRoot()) {
                fa_ = 0.0;
                root = b;
                return true;
            }
        }
        return false;
    }

private:
    Expansion<N> p_;            // declared before derivative_, which is built from p_.d1
    Walker<N - 1> derivative_;
    double hi_;
    double a_;                  // the walk has covered (lo, a_]
    double fa_;                 // p(a_), or 0 where a_ was taken as a root
    bool aCritical_ = false;    // a_ is a critical point
    bool aIsLo_ = true;         // a_ is lo
    bool done_ = false;
};

// Degree two in closed form: the stable quadratic formula (no cancellation between -B and the
// square root), with a discriminant within its rounding error taken as zero, a double root.
template <>
class Walker<2> {
public:
    Walker(const double* c, double lo, double hi)
    {
        const double A = c[0];
        const double B = c[1];
        const double C = c[2];
        const double discriminant = B * B - 4.0 * A * C;
        const double noise = kZeroTolerance * (B * B + 4.0 * std::abs(A * C));
        double roots[2];
        int n = 0;
        if (std::abs(discriminant) <= noise) {
            roots[n++] = -B / (2.0 * A);
        } else if (discriminant > 0.0) {
            const double q = -0.5 * (B + std::copysign(std::sqrt(discriminant), B));
            const double r1 = q / A;
            const double r2 = C / q;  // q != 0: discriminant > noise >= 0 means B != 0 or A C < 0
            roots[n++] = std::min(r1, r2);
            roots[n++] = std::max(r1, r2);
        }
        for (int i = 0; i < n; ++i)
            if (roots[i] > lo && roots[i] <= hi) roots_[count_++] = roots[i];
    }

    bool next(double& root)
    {
        if (taken_ == count_) return false;
        root = roots_[taken_++];
        return true;
    }

private:
    double roots_[2] = {0.0, 0.0};
    int count_ = 0;
    int taken_ = 0;
};

template <>
class Walker<1> {
public:
    Walker(const double* c, double lo, double hi)
        : root_(-c[1] / c[0]), pending_(root_ > lo && root_ <= hi)
    {
    }

    bool next(double& root)
    {
        if (!pending_) return false;
        pending_ = false;
        root = root_;
        return true;
    }

private:
    double root_;
    bool pending_;
};

// A polynomial prepared for root finding: scaled by a power of two (exact) when its coefficients are
// extreme, negligible leading coefficients dropped, and a bound on its roots.
struct Normalised {
    std::array<double, 5> c{};  // c[0 .. degree] hold the coefficients, highest degree first
    int degree = -1;            // -1: no usable polynomial (all zero, or not finite)
    double bound = 0.0;         // every root t satisfies |t| < bound
};

Normalised normalise(const Quartic& input)
{
    Normalised n;
    // An eighth of sum |c_i|: cannot overflow for finite coefficients, is infinite or NaN otherwise.
    double total = 0.0;
    for (double v : input) total += 0.125 * std::abs(v);
    if (!(total > 0.0 && total <= std::numeric_limits<double>::max())) return n;  // 0, inf or NaN

    int first = 0;
    while (std::abs(input[first]) <= kNegligibleLeading * total) ++first;
    n.degree = 4 - first;
    // Scaling keeps |p(bound)| <~ total 2^600 finite; in the usual range it is not needed.
    if (total > 0x1p300 || total < 0x1p-300) {
        const int exponent = std::ilogb(total);
        for (int i = 0; i <= n.degree; ++i) n.c[i] = std::ldexp(input[first + i], -exponent);
    } else {
        for (int i = 0; i <= n.degree; ++i) n.c[i] = input[first + i];
    }

    // Every root has |t| < 1 + 2 S / |c_0|, with S = sum over i > 0 of |c_i| (a Cauchy-type bound:
    // for t >= that bound, |c_0| |t|^n - S |t|^(n-1) >= |c_0| |t|^n / 2). So p(+-bound) is at least
    // half the leading term, and its sign is not at the mercy of rounding.
    double rest = 0.0;
    for (int i = 1; i <= n.degree; ++i) rest += std::abs(n.c[i]);
    n.bound = 1.0 + 2.0 * rest / std::abs(n.c[0]);
    return n;
}

// Calls visit(root) for each real root in (lo, hi] in ascending order until it returns false.
template <int N, typename Visit>
void visitRoots(const double* c, double lo, double hi, Visit visit)
{
    Walker<N> walker(c, lo, hi);
    double root = 0.0;
    while (walker.next(root))
        if (!visit(root)) return;
}

template <typename Visit>
void visitRootsOfNormalised(const Normalised& n, double lo, double hi, Visit visit)
{
    lo = std::max(lo, -n.bound);
    hi = std::min(hi, n.bound);
    if (!(lo < hi)) return;  // also false for NaN
    switch (n.degree) {
    case 4: visitRoots<4>(n.c.data(), lo, hi, visit); break;
    case 3: visitRoots<3>(n.c.data(), lo, hi, visit); break;
    case 2: visitRoots<2>(n.c.data(), lo, hi, visit); break;
    case 1: visitRoots<1>(n.c.data(), lo, hi, visit); break;
    default: break;
    }
}

}  // namespace

int solveQuartic(const Quartic& c, std::array<double, 4>& roots)
{
    int count = 0;
    visitRootsOfNormalised(normalise(c), -kInfinity, kInfinity, [&](double root) {
        roots[count++] = root;
        return count < 4;
    });
    return count;
}

double smallestRootInInterval(const Quartic& c, double lo, double hi)
{
    double smallest = kInfinity;
    visitRootsOfNormalised(normalise(c), lo, hi, [&](double root) {
        smallest = root;
        return false;
    });
    return smallest;
}

double smallestOcticRootInInterval(const Octic& input, double lo, double hi)
{
    // As normalise(): an eighth of sum |c_i| decides which leading coefficients are negligible,
    // scaling by a power of two keeps the values finite, and the Cauchy-type bound limits the walk.
    double total = 0.0;
    for (double v : input) total += 0.125 * std::abs(v);
    if (!(total > 0.0 && total <= std::numeric_limits<double>::max())) return kInfinity;
    int first = 0;
    while (std::abs(input[static_cast<std::size_t>(first)]) <= kNegligibleLeading * total) ++first;
    const int degree = 8 - first;
    if (degree <= 4) {
        Quartic q{};
        for (int i = 0; i <= degree; ++i) q[static_cast<std::size_t>(4 - degree + i)] = input[static_cast<std::size_t>(first + i)];
        return smallestRootInInterval(q, lo, hi);
    }
    double c[9] = {};
    const bool scale = total > 0x1p300 || total < 0x1p-300;
    const int exponent = scale ? std::ilogb(total) : 0;
    for (int i = 0; i <= degree; ++i) c[i] = std::ldexp(input[static_cast<std::size_t>(first + i)], -exponent);
    double rest = 0.0;
    for (int i = 1; i <= degree; ++i) rest += std::abs(c[i]);
    const double bound = 1.0 + 2.0 * rest / std::abs(c[0]);
    lo = std::max(lo, -bound);
    hi = std::min(hi, bound);
    if (!(lo < hi)) return kInfinity;
    double smallest = kInfinity;
    auto take = [&](double root) {
        smallest = root;
        return false;
    };
    switch (degree) {
    case 8: visitRoots<8>(c, lo, hi, take); break;
    case 7: visitRoots<7>(c, lo, hi, take); break;
    case 6: visitRoots<6>(c, lo, hi, take); break;
    default: visitRoots<5>(c, lo, hi, take); break;
    }
    return smallest;
}

int solveQuadratic(double c2, double c1, double c0, std::array<double, 2>& roots)
{
    if (c2 == 0.0) {
        if (c1 == 0.0) return 0;
        roots[0] = -c0 / c1;
        return 1;
    }
    const double disc = c1 * c1 - 4.0 * c2 * c0;
    if (disc < 0.0) return 0;
    const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
    if (q == 0.0) {  // c0 = c1 = 0
        roots[0] = 0.0;
        return 1;
    }
    const double r1 = q / c2, r2 = c0 / q;
    roots[0] = std::min(r1, r2);
    roots[1] = std::max(r1, r2);
    return 2;
}

}  // namespace cuelab
