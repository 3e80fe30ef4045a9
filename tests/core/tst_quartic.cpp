// The quartic root solver: known roots (simple, double, near-double, quadruple, complex), degenerate
// leading coefficients, the ends of the interval, wide scales, ball-ball contact quartics (including
// grazing contacts) and randomised quartics, each against a reference in binary128 (__float128).

#include "Quartic.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

using namespace cuelab;

namespace {

__extension__ typedef __float128 Quad;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

Quad absolute(Quad x) { return x < 0 ? -x : x; }

// Coefficients highest degree first, in binary128.
using QuadPoly = std::array<Quad, 5>;

// The monic-times-scale polynomial with the given real roots and complex pairs alpha +- i beta
// (pairs as alpha, beta, alpha, beta, ...), four roots in all, computed in binary128.
QuadPoly polyFromRoots(const QList<double>& realRoots, const QList<double>& pairs, double scale)
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

Quartic rounded(const QuadPoly& p)
{
    Quartic c{};
    for (int i = 0; i < 5; ++i) c[i] = static_cast<double>(p[i]);
    return c;
}

bool representedExactly(const QuadPoly& p)
{
    for (int i = 0; i < 5; ++i)
        if (Quad(static_cast<double>(p[i])) != p[i]) return false;
    return true;
}

struct QuadValue {
    Quad f = 0;
    Quad df = 0;
};

QuadValue evaluate(const Quartic& c, Quad x)
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
double polish(const Quartic& c, double start)
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
double simpleRootTolerance(const Quartic& c, double r)
{
    double magnitude = 0.0;
    for (int i = 0; i < 5; ++i) magnitude = magnitude * std::abs(r) + std::abs(c[i]);
    const double slope = std::abs(static_cast<double>(evaluate(c, r).df));
    const double plain = 64.0 * kEpsilon * magnitude / slope;
    const double compensated = 64.0 * kEpsilon * kEpsilon * magnitude / slope;
    return std::min(plain, 1e-12 * std::abs(r)) + compensated + 4.0 * kEpsilon * std::abs(r);
}

QString describe(const Quartic& c)
{
    return QString::asprintf("c = {%.17g, %.17g, %.17g, %.17g, %.17g}", c[0], c[1], c[2], c[3], c[4]);
}

// The smallest value in sorted `roots` with lo < r <= hi, +infinity if none.
double smallestIn(const std::vector<double>& roots, double lo, double hi)
{
    for (double r : roots)
        if (r > lo && r <= hi) return r;
    return kInfinity;
}

bool within(double x, double reference, double relTol)
{
    if (std::isinf(reference) || std::isinf(x)) return x == reference;
    return std::abs(x - reference) <= relTol * std::abs(reference);
}

// Relative position of two balls, dr(t) = P + V t + A t^2 (A is half the relative acceleration), m.
struct Relative {
    double px, py, vx, vy, ax, ay;
};

// |dr(t)|^2 - d^2 with d the contact distance (sum of the radii), as a caller builds it.
Quartic contactQuartic(const Relative& r, double d)
{
    return {r.ax * r.ax + r.ay * r.ay, 2.0 * (r.ax * r.vx + r.ay * r.vy),
            r.vx * r.vx + r.vy * r.vy + 2.0 * (r.ax * r.px + r.ay * r.py),
            2.0 * (r.px * r.vx + r.py * r.vy), r.px * r.px + r.py * r.py - d * d};
}

// The contact time next to `start` from the geometry itself, |dr(t)| = d, by Newton in binary128.
double contactTime(const Relative& r, double d, double start)
{
    Quad t = start;
    for (int iteration = 0; iteration < 400; ++iteration) {
        const Quad x = Quad(r.px) + Quad(r.vx) * t + Quad(r.ax) * t * t;
        const Quad y = Quad(r.py) + Quad(r.vy) * t + Quad(r.ay) * t * t;
        const Quad dx = Quad(r.vx) + 2 * Quad(r.ax) * t;
        const Quad dy = Quad(r.vy) + 2 * Quad(r.ay) * t;
        const Quad f = x * x + y * y - Quad(d) * Quad(d);
        const Quad df = 2 * (x * dx + y * dy);
        if (df == 0) break;
        const Quad step = f / df;
        t -= step;
        if (absolute(step) <= Quad(1e-33) * absolute(t)) break;
    }
    return static_cast<double>(t);
}

constexpr double kBallRadius = 0.028575;  // m, WPA pool ball
constexpr double kContact = 2.0 * kBallRadius;  // m, centre distance at contact

}  // namespace

Q_DECLARE_METATYPE(Relative)
Q_DECLARE_METATYPE(cuelab::Quartic)

class TestQuartic : public QObject {
    Q_OBJECT
private slots:
    void knownRoots_data();
    void knownRoots();
    void degenerateLeadingCoefficient_data();
    void degenerateLeadingCoefficient();
    void regressions_data();
    void regressions();
    void intervalEnds_data();
    void intervalEnds();
    void ballBallContact_data();
    void ballBallContact();
    void grazingContactsAreNeverMissed();
    void grazingContactRestartMovesOn();
    void randomQuartics_data();
    void randomQuartics();
    void nonFiniteInput();

private:
    void checkGivenCoefficients();
};

// Quartics with exactly known roots. Rows flagged exact have dyadic roots whose products fit in 53
// bits, so the double coefficients are exact and the listed roots are the true roots of what the
// solver sees (other rows polish them on the rounded coefficients in binary128). A simple root must
// be within simpleRootTolerance, which stays near eps even for close pairs (they are resolved down
// to 1e-12 apart); a multiple root within the row's tolerance.
void TestQuartic::knownRoots_data()
{
    QTest::addColumn<QList<double>>("realRoots");  // with multiplicity
    QTest::addColumn<QList<double>>("pairs");      // complex pairs: alpha, beta, ...
    QTest::addColumn<double>("scale");             // leading coefficient
    QTest::addColumn<bool>("exact");               // coefficients must be exact in double
    QTest::addColumn<double>("multipleTol");       // relative, for roots listed more than once
    QTest::addColumn<bool>("resolvesAll");         // every root reported, once (else double roots
                                                   // and close pairs may come out once or twice)

    const double near6 = 1.0 + std::ldexp(1.0, -20);  // 1 + 9.5e-7
    const double near9 = 1.0 + std::ldexp(1.0, -30);  // 1 + 9.3e-10
    const double near12 = 1.0 + std::ldexp(1.0, -40);  // 1 + 9.1e-13
    QTest::newRow("simple-1-2-3-4") << QList<double>{1, 2, 3, 4} << QList<double>{} << 1.0 << true << 4 * kEpsilon << true;
    QTest::newRow("simple-mixed-signs") << QList<double>{-1.5, 0.5, 2.25, 3} << QList<double>{} << -2.0 << true << 4 * kEpsilon << true;
    QTest::newRow("simple-and-pair") << QList<double>{-0.75, 1.25} << QList<double>{0.5, 0.25} << 3.0 << true << 4 * kEpsilon << true;
    QTest::newRow("double-root") << QList<double>{1, 1, 3, -2} << QList<double>{} << 1.0 << true << 1e-14 << false;
    QTest::newRow("double-root-and-pair") << QList<double>{0.625, 0.625} << QList<double>{2, 0.5} << -1.0 << true << 1e-14 << false;
    QTest::newRow("two-double-roots") << QList<double>{0.5, 0.5, 2, 2} << QList<double>{} << 1.0 << true << 1e-14 << false;
    QTest::newRow("triple-root") << QList<double>{1.5, 1.5, 1.5, -1} << QList<double>{} << 1.0 << true << 1e-10 << false;
    QTest::newRow("quadruple-root") << QList<double>{1.5, 1.5, 1.5, 1.5} << QList<double>{} << 1.0 << true << 1e-10 << false;
    QTest::newRow("near-double-1e-6") << QList<double>{1, near6, 3, -2} << QList<double>{} << 1.0 << true << 0.0 << true;
    QTest::newRow("near-double-1e-9") << QList<double>{1, near9, 3, -2} << QList<double>{} << 1.0 << true << 0.0 << true;
    QTest::newRow("near-double-1e-12") << QList<double>{1, near12, 3, -2} << QList<double>{} << 1.0 << true << 0.0 << true;
    QTest::newRow("near-double-pair-and-pair") << QList<double>{0.75, near9 * 0.75} << QList<double>{-1, 0.5} << -3.0 << true << 0.0 << true;
    QTest::newRow("root-at-zero") << QList<double>{0, 1, 2, -1} << QList<double>{} << 1.0 << true << 4 * kEpsilon << true;
    QTest::newRow("no-real-root") << QList<double>{} << QList<double>{0, 1, 2, 0.5} << 1.0 << true << 0.0 << true;
    QTest::newRow("no-real-root-close-to-axis") << QList<double>{} << QList<double>{1, 0.001, -1, 0.001} << 1.0 << false << 0.0 << true;
    QTest::newRow("wide-scale-1e-6-1e3") << QList<double>{1e-6, 1e3} << QList<double>{1, 1} << 1.0 << false << 1e-13 << true;
    QTest::newRow("wide-scale-four") << QList<double>{1e-6, 1e-3, 1, 1e3} << QList<double>{} << 1.0 << false << 1e-13 << true;
    QTest::newRow("huge-coefficients") << QList<double>{1, 2, 3, 4} << QList<double>{} << std::ldexp(1.0, 830) << true << 4 * kEpsilon << true;
    QTest::newRow("tiny-coefficients") << QList<double>{1, 2, 3, 4} << QList<double>{} << std::ldexp(1.0, -830) << true << 4 * kEpsilon << true;
}

void TestQuartic::knownRoots()
{
    QFETCH(QList<double>, realRoots);
    QFETCH(QList<double>, pairs);
    QFETCH(double, scale);
    QFETCH(bool, exact);
    QFETCH(double, multipleTol);
    QFETCH(bool, resolvesAll);

    const QuadPoly exactPoly = polyFromRoots(realRoots, pairs, scale);
    const Quartic c = rounded(exactPoly);
    if (exact) QVERIFY2(representedExactly(exactPoly), "row meant to have exact coefficients");

    // Reference: the distinct roots, polished on the rounded coefficients when those are inexact,
    // each with its tolerance.
    std::vector<double> reference;
    std::vector<double> tolerance;
    for (double r : realRoots) {
        if (std::find(reference.begin(), reference.end(), r) != reference.end()) continue;
        const bool multiple = realRoots.count(r) > 1;
        reference.push_back(exact || multiple ? r : polish(c, r));
        tolerance.push_back(multiple ? multipleTol * std::abs(r) : simpleRootTolerance(c, reference.back()));
    }

    std::array<double, 4> roots{};
    const int count = solveQuartic(c, roots);
    QVERIFY2(count >= 0 && count <= 4, qPrintable(describe(c)));
    QVERIFY2(std::is_sorted(roots.begin(), roots.begin() + count), qPrintable(describe(c)));
    if (resolvesAll) QCOMPARE(count, static_cast<int>(reference.size()));
    for (std::size_t j = 0; j < reference.size(); ++j) {  // none missed
        bool found = false;
        for (int i = 0; i < count; ++i) found = found || std::abs(roots[i] - reference[j]) <= tolerance[j];
        QVERIFY2(found, qPrintable(QString("root %1 missed, %2").arg(reference[j], 0, 'g', 17).arg(describe(c))));
    }
    for (int i = 0; i < count; ++i) {  // none invented
        bool known = false;
        for (std::size_t j = 0; j < reference.size(); ++j)
            known = known || std::abs(roots[i] - reference[j]) <= tolerance[j];
        QVERIFY2(known, qPrintable(QString("root %1 invented, %2").arg(roots[i], 0, 'g', 17).arg(describe(c))));
    }

    double expected = kInfinity;
    double expectedTolerance = 0.0;
    for (std::size_t j = 0; j < reference.size(); ++j) {
        if (reference[j] > 0.0 && reference[j] < expected) {
            expected = reference[j];
            expectedTolerance = tolerance[j];
        }
    }
    const double first = smallestRootInInterval(c, 0.0, kInfinity);
    const bool agrees = std::isinf(expected) ? std::isinf(first) : std::abs(first - expected) <= expectedTolerance;
    QVERIFY2(agrees, qPrintable(QString("smallest positive %1, expected %2, %3")
                                    .arg(first, 0, 'g', 17).arg(expected, 0, 'g', 17).arg(describe(c))));
}

// A leading coefficient that vanishes, exactly or nearly: the polynomial is a cubic, quadratic or
// linear one, or keeps a fourth root far away (t ~ -c1 / c0).
void TestQuartic::degenerateLeadingCoefficient_data()
{
    QTest::addColumn<Quartic>("c");
    QTest::addColumn<QList<double>>("expected");  // roots, or starting points polished on c
    QTest::addColumn<bool>("polishExpected");

    QTest::newRow("cubic-exact-zero") << Quartic{0, 1, -6, 11, -6} << QList<double>{1, 2, 3} << false;
    QTest::newRow("cubic-1e-20") << Quartic{1e-20, 1, -6, 11, -6} << QList<double>{-1e20, 1, 2, 3} << true;
    QTest::newRow("cubic-minus-1e-20") << Quartic{-1e-20, 1, -6, 11, -6} << QList<double>{1, 2, 3, 1e20} << true;
    QTest::newRow("cubic-one-real-1e-12") << Quartic{1e-12, 2, 0, 2, 4} << QList<double>{-2e12, -1} << true;
    QTest::newRow("quadratic-exact-zero") << Quartic{0, 0, 1, -3, 2} << QList<double>{1, 2} << false;
    QTest::newRow("quadratic-1e-20-1e-20") << Quartic{1e-20, 1e-20, 1, -3, 2} << QList<double>{1, 2} << true;
    QTest::newRow("quadratic-double-root") << Quartic{0, 0, 4, -12, 9} << QList<double>{1.5} << false;
    QTest::newRow("quadratic-no-root") << Quartic{0, 0, 1, 0, 1} << QList<double>{} << false;
    QTest::newRow("quadratic-tiny-leading") << Quartic{0, 0, 1e-20, 1, -1} << QList<double>{-1e20, 1} << true;
    QTest::newRow("linear") << Quartic{0, 0, 0, 2, -3} << QList<double>{1.5} << false;
    QTest::newRow("linear-1e-30-leading") << Quartic{1e-30, 0, 0, 2, -3} << QList<double>{-1.2599210498948732e10, 1.5} << true;
    QTest::newRow("constant") << Quartic{0, 0, 0, 0, 5} << QList<double>{} << false;
    QTest::newRow("zero-polynomial") << Quartic{0, 0, 0, 0, 0} << QList<double>{} << false;
    QTest::newRow("negligible-leading-2^-210") << Quartic{std::ldexp(1.0, -210), 0, 1, -3, 2} << QList<double>{1, 2} << false;
    const double big = std::numeric_limits<double>::max();
    QTest::newRow("near-overflow-coefficients") << Quartic{big, -big, -big, big, -0.5 * big} << QList<double>{-1.1, 1.4} << true;
    const double tiny = std::numeric_limits<double>::denorm_min();
    QTest::newRow("subnormal-coefficients") << Quartic{tiny, -10 * tiny, 0, 0, 0} << QList<double>{0, 10} << false;
}

void TestQuartic::degenerateLeadingCoefficient() { checkGivenCoefficients(); }

// Quartics that once defeated the solver in randomised searches.
void TestQuartic::regressions_data()
{
    QTest::addColumn<Quartic>("c");
    QTest::addColumn<QList<double>>("expected");
    QTest::addColumn<bool>("polishExpected");
    // A close pair (2.7e-6 apart) whose critical point came from a Halley step trusted too early:
    // its error estimate was 100 times too small, p there had the wrong sign, and both roots were
    // missed.
    QTest::newRow("close-pair-early-stop") << Quartic{2.9367977100187428, -1.141899882645705, 0.21557466659376132,
                                                      -0.023903349077570007, 0.0011342121677588698}
                                           << QList<double>{0.12955479242254947, 0.12955514780556224} << true;
}

void TestQuartic::regressions() { checkGivenCoefficients(); }

// Rows with columns c, expected, polishExpected: solveQuartic must give exactly the expected roots
// (polished in binary128 on c when flagged) to 1e-14, and smallestRootInInterval the right one.
void TestQuartic::checkGivenCoefficients()
{
    QFETCH(Quartic, c);
    QFETCH(QList<double>, expected);
    QFETCH(bool, polishExpected);

    std::vector<double> reference;
    for (double r : expected) reference.push_back(polishExpected ? polish(c, r) : r);
    std::sort(reference.begin(), reference.end());

    std::array<double, 4> roots{};
    const int count = solveQuartic(c, roots);
    QCOMPARE(count, static_cast<int>(reference.size()));
    for (int i = 0; i < count; ++i)
        QVERIFY2(within(roots[i], reference[i], 1e-14),
                 qPrintable(QString("root %1: %2, expected %3")
                                .arg(i).arg(roots[i], 0, 'g', 17).arg(reference[i], 0, 'g', 17)));
    const double first = smallestRootInInterval(c, 0.0, kInfinity);
    QVERIFY(within(first, smallestIn(reference, 0.0, kInfinity), 1e-14));
    const double firstAfterMinusOne = smallestRootInInterval(c, -1.0, 10.0);
    QVERIFY(within(firstAfterMinusOne, smallestIn(reference, -1.0, 10.0), 1e-14));
}

// The interval is (lo, hi]: a root at lo is skipped, a root at hi is taken.
void TestQuartic::intervalEnds_data()
{
    QTest::addColumn<Quartic>("c");
    QTest::addColumn<double>("lo");
    QTest::addColumn<double>("hi");
    QTest::addColumn<double>("expected");

    const Quartic p1234{1, -10, 35, -50, 24};  // (t - 1)(t - 2)(t - 3)(t - 4), exact
    const Quartic zeroRoot{1, -2, -1, 2, 0};   // t (t + 1)(t - 1)(t - 2), exact
    QTest::newRow("lo-on-root-skips-it") << p1234 << 1.0 << 10.0 << 2.0;
    QTest::newRow("hi-on-root-takes-it") << p1234 << 0.0 << 1.0 << 1.0;
    QTest::newRow("lo-and-hi-on-roots") << p1234 << 2.0 << 3.0 << 3.0;
    QTest::newRow("between-roots") << p1234 << 2.0 << 2.9 << kInfinity;
    QTest::newRow("before-all-roots") << p1234 << -kInfinity << 0.5 << kInfinity;
    QTest::newRow("after-all-roots") << p1234 << 4.0 << kInfinity << kInfinity;
    QTest::newRow("last-root-at-hi") << p1234 << 3.5 << 4.0 << 4.0;
    QTest::newRow("empty-interval") << p1234 << 2.0 << 2.0 << kInfinity;
    QTest::newRow("reversed-interval") << p1234 << 3.0 << 1.0 << kInfinity;
    QTest::newRow("whole-line") << p1234 << -kInfinity << kInfinity << 1.0;
    QTest::newRow("root-at-zero-excluded") << zeroRoot << 0.0 << 5.0 << 1.0;
    QTest::newRow("root-at-zero-included") << zeroRoot << -0.5 << 5.0 << 0.0;
    QTest::newRow("root-at-zero-as-hi") << zeroRoot << -0.5 << 0.0 << 0.0;
    QTest::newRow("negative-root") << zeroRoot << -kInfinity << 5.0 << -1.0;
    QTest::newRow("nan-lo") << p1234 << std::nan("") << 5.0 << kInfinity;
}

void TestQuartic::intervalEnds()
{
    QFETCH(Quartic, c);
    QFETCH(double, lo);
    QFETCH(double, hi);
    QFETCH(double, expected);
    QCOMPARE(smallestRootInInterval(c, lo, hi), expected);  // exact coefficients, exact roots
}

// Two balls whose relative position is quadratic in t (sliding or rolling with friction); the
// contact time is the smallest root of |dr(t)|^2 - (2R)^2. The reference solves the geometry in
// binary128 from a starting guess. Grazing rows touch exactly once (a double root); rounding the
// coefficients may push the exact polynomial's minimum a hair either side of zero, and the solver
// must still report the touch, to within the sqrt(eps) conditioning of a double root.
void TestQuartic::ballBallContact_data()
{
    QTest::addColumn<Relative>("relative");
    QTest::addColumn<double>("guess");    // s, next to the contact; < 0 for none expected
    QTest::addColumn<bool>("grazing");    // guess is the exact touch time (a double root)
    QTest::addColumn<double>("relTol");

    const double d = kContact;
    const double rolling = 0.5 * 0.01 * 9.81;  // m/s^2, half the rolling deceleration mu_r g
    const double sliding = 0.5 * 0.2 * 9.81;   // m/s^2, half the sliding deceleration mu_s g
    QTest::newRow("head-on-constant-speed") << Relative{-0.5, 0, 2, 0, 0, 0} << 0.2 << false << 1e-14;
    QTest::newRow("head-on-rolling") << Relative{-0.5, 0, 2, 0, -rolling, 0} << 0.2 << false << 1e-14;
    QTest::newRow("half-ball-cut-rolling") << Relative{-0.8, kBallRadius, 1.5, 0, -rolling, 0} << 0.5 << false << 1e-14;
    QTest::newRow("cut-sliding-curving") << Relative{-0.6, 0.1, 1.5, -0.1, -0.6 * sliding, -0.1 * sliding} << 0.45 << false << 1e-13;
    QTest::newRow("overtaking") << Relative{-0.3, 0.01, 0.4, 0, -0.02, 0.001} << 0.63 << false << 1e-13;
    QTest::newRow("slow-stop-just-short") << Relative{-0.3, 0, 0.2, 0, -0.1, 0} << -1.0 << false << 0.0;
    QTest::newRow("receding") << Relative{0.3, 0.1, 0.5, 0.2, -0.05, -0.02} << -1.0 << false << 0.0;
    QTest::newRow("touching-at-0-separating") << Relative{d, 0, 1, 0, -rolling, 0} << -1.0 << false << 0.0;
    // Path coordinate x(t) = -s + v t - a t^2 reaches 0 at t = 2 s / (v + sqrt(v^2 - 4 a s)).
    auto touch = [](double s, double v, double a) { return 2.0 * s / (v + std::sqrt(v * v - 4.0 * a * s)); };
    QTest::newRow("grazing-constant-speed") << Relative{-0.4, d, 1, 0, 0, 0} << 0.4 << true << 3e-8;
    QTest::newRow("grazing-rolling") << Relative{-0.4, d, 1.2, 0, -rolling, 0} << touch(0.4, 1.2, rolling) << true << 3e-8;
    QTest::newRow("grazing-sliding") << Relative{-0.25, -d, 1.1, 0, -sliding, 0} << touch(0.25, 1.1, sliding) << true << 3e-8;
    const double u = std::cos(0.7);
    const double w = std::sin(0.7);  // grazing along the direction (u, w), offset d along (-w, u)
    QTest::newRow("grazing-diagonal") << Relative{-0.45 * u - d * w, -0.45 * w + d * u, 1.3 * u, 1.3 * w,
                                                 -rolling * u, -rolling * w}
                                        << touch(0.45, 1.3, rolling) << true << 3e-8;
    QTest::newRow("near-miss-1um") << Relative{-0.4, d + 1e-6, 1, 0, -rolling, 0} << -1.0 << false << 0.0;
    QTest::newRow("overlap-1um") << Relative{-0.4, d - 1e-6, 1, 0, -rolling, 0} << 0.4078 << false << 1e-9;
}

void TestQuartic::ballBallContact()
{
    QFETCH(Relative, relative);
    QFETCH(double, guess);
    QFETCH(bool, grazing);
    QFETCH(double, relTol);

    const Quartic c = contactQuartic(relative, kContact);
    const double expected = guess < 0.0 ? kInfinity : grazing ? guess : contactTime(relative, kContact, guess);
    const double t = smallestRootInInterval(c, 0.0, 10.0);
    QVERIFY2(within(t, expected, relTol),
             qPrintable(QString("contact at %1 s, expected %2 s, %3")
                            .arg(t, 0, 'g', 17).arg(expected, 0, 'g', 17).arg(describe(c))));
}

// Thousands of exactly grazing contacts at random angles, speeds and decelerations: rounding the
// coefficients leaves each a double root within rounding, and none may be missed.
void TestQuartic::grazingContactsAreNeverMissed()
{
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int missed = 0;
    double worst = 0.0;
    constexpr int kCases = 4000;
    for (int k = 0; k < kCases; ++k) {
        const double angle = 2.0 * std::numbers::pi * unit(random);
        const double u = std::cos(angle);
        const double w = std::sin(angle);
        const double distance = 0.05 + 2.0 * unit(random);  // m along the path to the touch
        const double speed = 0.2 + 3.0 * unit(random);      // m/s
        // Half the deceleration, small enough that the ball gets there: v^2 > 4 a s.
        const double halfDeceleration = unit(random) * 0.9 * speed * speed / (4.0 * distance);
        const double side = (k % 2 == 0) ? 1.0 : -1.0;
        const Relative r{-distance * u - side * kContact * w, -distance * w + side * kContact * u,
                         speed * u, speed * w, -halfDeceleration * u, -halfDeceleration * w};
        // Path x(t) = -distance + speed t - a t^2 reaches 0 first at this time.
        const double touch = 2.0 * distance / (speed + std::sqrt(speed * speed - 4.0 * halfDeceleration * distance));
        const double t = smallestRootInInterval(contactQuartic(r, kContact), 0.0, 100.0);
        if (std::isinf(t)) {
            ++missed;
            continue;
        }
        worst = std::max(worst, std::abs(t - touch) / touch);
    }
    QCOMPARE(missed, 0);
    QVERIFY2(worst <= 3e-7, qPrintable(QString("worst relative error %1").arg(worst)));
}

// Event detection restarts the search from the contact just found. A grazing contact is a double
// root, which rounding may split into two nearly equal roots (Quartic.h): restarting must report it at
// most twice (the simulation would otherwise stall on it) and must then find the second touch, where
// the decelerating path comes back to x = 0, also a double root, at
// (speed + sqrt(speed^2 - 4 a distance)) / (2 a), or nothing when that lies beyond the interval.
void TestQuartic::grazingContactRestartMovesOn()
{
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    constexpr double kHorizon = 100.0;  // s, the interval searched
    constexpr double kDoubleRootTolerance = 3e-7;  // relative, the sqrt(eps) conditioning of a touch
    int stalled = 0;
    int wrongAfter = 0;  // the second touch missed, or a root invented after the first
    int split = 0;
    double worst = 0.0;
    constexpr int kCases = 2000;
    for (int k = 0; k < kCases; ++k) {
        const double angle = 2.0 * std::numbers::pi * unit(random);
        const double u = std::cos(angle);
        const double w = std::sin(angle);
        const double distance = 0.05 + 2.0 * unit(random);  // m along the path to the touch
        const double speed = 0.2 + 3.0 * unit(random);      // m/s
        // Half the deceleration, m/s^2: at least 0.05 of the most that still reaches the touch, so
        // that the second touch is well apart from the first.
        const double halfDeceleration = (0.05 + 0.85 * unit(random)) * speed * speed / (4.0 * distance);
        const double side = (k % 2 == 0) ? 1.0 : -1.0;
        const Relative r{-distance * u - side * kContact * w, -distance * w + side * kContact * u,
                         speed * u, speed * w, -halfDeceleration * u, -halfDeceleration * w};
        const double root = std::sqrt(speed * speed - 4.0 * halfDeceleration * distance);
        const double firstTouch = 2.0 * distance / (speed + root);
        const double secondTouch = (speed + root) / (2.0 * halfDeceleration);
        const Quartic c = contactQuartic(r, kContact);
        double t = smallestRootInInterval(c, 0.0, kHorizon);
        QVERIFY2(within(t, firstTouch, kDoubleRootTolerance), qPrintable(describe(c)));
        int reports = 1;
        for (;;) {
            const double next = smallestRootInInterval(c, t, kHorizon);
            if (!within(next, firstTouch, kDoubleRootTolerance)) {
                t = next;
                break;
            }
            t = next;
            if (++reports > 2) break;
        }
        if (reports > 2) {
            ++stalled;
            continue;
        }
        if (reports == 2) ++split;
        if (secondTouch > kHorizon) {
            if (!std::isinf(t)) ++wrongAfter;  // a root reported where there is none
            continue;
        }
        if (std::isinf(t)) {
            ++wrongAfter;
            continue;
        }
        worst = std::max(worst, std::abs(t - secondTouch) / secondTouch);
    }
    qInfo("%d of %d grazing contacts reported as a split pair", split, kCases);
    QCOMPARE(stalled, 0);
    QCOMPARE(wrongAfter, 0);
    QVERIFY2(worst <= kDoubleRootTolerance, qPrintable(QString("worst relative error of the second touch %1").arg(worst)));
}

// Random quartics from random roots. Well separated roots must all be found, within
// simpleRootTolerance; close pairs (1e-6 to 1e-3 apart) too. Checks solveQuartic's count and values, that chaining
// smallestRootInInterval from root to root finds the same roots, and the smallest root in a random
// interval.
void TestQuartic::randomQuartics_data()
{
    QTest::addColumn<double>("minSeparation");
    QTest::addColumn<bool>("closePair");
    QTest::addColumn<bool>("tinyLeading");
    QTest::addColumn<unsigned>("seed");
    QTest::newRow("separated") << 0.01 << false << false << 1u;
    QTest::newRow("close-pair") << 0.01 << true << false << 2u;
    QTest::newRow("tiny-leading") << 0.01 << false << true << 3u;
}

void TestQuartic::randomQuartics()
{
    QFETCH(double, minSeparation);
    QFETCH(bool, closePair);
    QFETCH(bool, tinyLeading);
    QFETCH(unsigned, seed);

    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto position = [&] { return -4.0 + 8.0 * unit(random); };
    constexpr int kCases = 3000;
    int checkedIntervals = 0;
    for (int k = 0; k < kCases; ++k) {
        QList<double> realRoots;
        QList<double> pairs;
        const int pairCount = static_cast<int>(random() % 3);
        if (tinyLeading) {  // a cubic with a fourth root at 1e6 .. 1e16: leading coefficient ~ 1 / R
            realRoots.push_back(((k % 2 == 0) ? 1.0 : -1.0) * std::pow(10.0, 6.0 + 10.0 * unit(random)));
        }
        const int realCount = 4 - 2 * pairCount - static_cast<int>(realRoots.size());
        if (realCount < 0) {
            --k;
            continue;
        }
        auto farEnough = [&](double r) {
            for (double s : realRoots)
                if (std::abs(s) < 1e5 && std::abs(r - s) < minSeparation) return false;
            return true;
        };
        if (closePair && realCount >= 2) {
            const double r = position();
            const double delta = std::pow(10.0, -6.0 + 3.0 * unit(random));
            realRoots.push_back(r);
            realRoots.push_back(r + delta * std::max(1.0, std::abs(r)));
        }
        while (realRoots.size() < realCount + (tinyLeading ? 1 : 0)) {
            const double r = position();
            if (farEnough(r)) realRoots.push_back(r);
        }
        for (int i = 0; i < pairCount; ++i) {
            pairs.push_back(position());
            pairs.push_back(0.05 + unit(random));
        }
        const double scale = (tinyLeading ? 1.0 / -realRoots.front() : 1.0) *
                             ((random() % 2 == 0) ? 1.0 : -1.0) * std::pow(10.0, -2.0 + 4.0 * unit(random));
        const Quartic c = rounded(polyFromRoots(realRoots, pairs, scale));

        std::vector<double> reference;
        for (double r : realRoots) reference.push_back(polish(c, r));
        std::sort(reference.begin(), reference.end());
        for (std::size_t i = 1; i < reference.size(); ++i)  // the reference itself is sound
            QVERIFY2(reference[i] > reference[i - 1], qPrintable(describe(c)));

        std::array<double, 4> roots{};
        const int count = solveQuartic(c, roots);
        QVERIFY2(count == static_cast<int>(reference.size()),
                 qPrintable(QString("%1 roots, expected %2, %3").arg(count).arg(reference.size()).arg(describe(c))));
        for (int i = 0; i < count; ++i) {
            const double tolerance = simpleRootTolerance(c, reference[i]);
            QVERIFY2(std::abs(roots[i] - reference[i]) <= tolerance,
                     qPrintable(QString("root %1, expected %2 (tolerance %3), %4")
                                    .arg(roots[i], 0, 'g', 17).arg(reference[i], 0, 'g', 17)
                                    .arg(tolerance).arg(describe(c))));
        }

        // Chaining smallestRootInInterval from each root found gives the same roots (up to rounding:
        // each call starts its iteration from a different bracket).
        double from = -kInfinity;
        for (int i = 0; i < count; ++i) {
            from = smallestRootInInterval(c, from, kInfinity);
            QVERIFY2(std::abs(from - roots[i]) <= 2.0 * simpleRootTolerance(c, reference[i]), qPrintable(QString("chained root %1: %2, solveQuartic %3, %4")
                                                      .arg(i).arg(from, 0, 'g', 17).arg(roots[i], 0, 'g', 17).arg(describe(c))));
        }
        QVERIFY2(std::isinf(smallestRootInInterval(c, from, kInfinity)), qPrintable(describe(c)));

        const double lo = position();
        const double hi = lo + 8.0 * unit(random);
        const double expected = smallestIn(reference, lo, hi);
        // Skip intervals whose ends sit within a root's tolerance of a root: either answer is right.
        bool ambiguous = false;
        for (double r : reference)
            ambiguous = ambiguous || std::abs(r - lo) <= 2.0 * simpleRootTolerance(c, r) ||
                        std::abs(r - hi) <= 2.0 * simpleRootTolerance(c, r);
        if (ambiguous) continue;
        ++checkedIntervals;
        const double t = smallestRootInInterval(c, lo, hi);
        if (std::isinf(expected)) {
            QVERIFY2(std::isinf(t), qPrintable(QString("invented root %1 in (%2, %3], %4")
                                                   .arg(t, 0, 'g', 17).arg(lo).arg(hi).arg(describe(c))));
        } else {
            QVERIFY2(std::abs(t - expected) <= simpleRootTolerance(c, expected),
                     qPrintable(QString("smallest root %1 in (%2, %3], expected %4, %5")
                                    .arg(t, 0, 'g', 17).arg(lo).arg(hi).arg(expected, 0, 'g', 17).arg(describe(c))));
        }
    }
    QVERIFY(checkedIntervals > kCases * 9 / 10);
}

void TestQuartic::nonFiniteInput()
{
    std::array<double, 4> roots{};
    const double nan = std::nan("");
    QCOMPARE(solveQuartic({1, nan, 0, 0, -1}, roots), 0);
    QCOMPARE(solveQuartic({1, 0, kInfinity, 0, -1}, roots), 0);
    QCOMPARE(smallestRootInInterval({1, 0, 0, 0, nan}, 0.0, 10.0), kInfinity);
    QCOMPARE(smallestRootInInterval({1, -10, 35, -50, 24}, 0.0, nan), kInfinity);
}

QTEST_APPLESS_MAIN(TestQuartic)
#include "tst_quartic.moc"
