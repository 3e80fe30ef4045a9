// The quartic root solver: known roots (simple, double, near-double, quadruple, complex), degenerate
// leading coefficients, the ends of the interval, wide scales and randomised quartics, each against a
// reference in binary128 (__float128, QuarticReference.h). Ball-ball contact quartics, grazing ones
// included: tst_contactquartic.

#include "QuarticReference.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

using namespace cuelab;
using namespace cuelab::quartictest;

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
