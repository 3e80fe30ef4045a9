// The root finders beside the quartic's (Quartic.h): solveQuadratic, which the cushion and flight
// detection share, and smallestOcticRootInInterval, the flying ball against a jaw's rim.

#include "Quartic.h"

#include <QtTest>

#include <array>
#include <cmath>
#include <limits>

using namespace cuelab;

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}

class TestRootFinders : public QObject {
    Q_OBJECT
private slots:
    void quadratics();
    void octics();
};

// Ascending roots, the linear and empty cases, and a small root kept exact where the textbook
// formula cancels.
void TestRootFinders::quadratics()
{
    std::array<double, 2> r{};
    QCOMPARE(solveQuadratic(1.0, -3.0, 2.0, r), 2);
    QCOMPARE(r[0], 1.0);
    QCOMPARE(r[1], 2.0);
    QCOMPARE(solveQuadratic(-2.0, 0.0, 8.0, r), 2);  // descending parabola: still ascending roots
    QCOMPARE(r[0], -2.0);
    QCOMPARE(r[1], 2.0);
    QCOMPARE(solveQuadratic(0.0, 2.0, -1.0, r), 1);  // linear
    QCOMPARE(r[0], 0.5);
    QCOMPARE(solveQuadratic(1.0, 0.0, 1.0, r), 0);   // no real root
    QCOMPARE(solveQuadratic(0.0, 0.0, 1.0, r), 0);   // a constant
    QCOMPARE(solveQuadratic(3.0, 0.0, 0.0, r), 1);   // c0 = c1 = 0: the double root at 0
    QCOMPARE(r[0], 0.0);
    // s^2 - 1e8 s + 1 = 0: roots about 1e-8 and 1e8; -b - sqrt(disc) style cancellation would lose
    // the small one entirely.
    QCOMPARE(solveQuadratic(1.0, -1e8, 1.0, r), 2);
    QVERIFY(std::abs(r[0] - 1e-8) <= 1e-22);
    QVERIFY(std::abs(r[1] - 1e8) <= 1e-6);
}

void TestRootFinders::octics()
{
    // The first root in (lo, hi] of a polynomial of degree up to eight (smallestOcticRootInInterval).
    // (t - 1)(t - 2) ... (t - 8), expanded exactly (integers): the walk over seven levels of
    // critical points finds each root, the one at lo excluded.
    const Octic wilkinson{1, -36, 546, -4536, 22449, -67284, 118124, -109584, 40320};
    QCOMPARE(smallestOcticRootInInterval(wilkinson, 0.0, 10.0), 1.0);
    QCOMPARE(smallestOcticRootInInterval(wilkinson, 1.0, 10.0), 2.0);
    QVERIFY(std::abs(smallestOcticRootInInterval(wilkinson, 7.5, 10.0) - 8.0) <= 1e-12);
    QCOMPARE(smallestOcticRootInInterval(wilkinson, 8.0, 100.0), kInfinity);
    QCOMPARE(smallestOcticRootInInterval(wilkinson, 0.0, 0.5), kInfinity);
    // t^8 - 1: only +-1 are real.
    QCOMPARE(smallestOcticRootInInterval(Octic{1, 0, 0, 0, 0, 0, 0, 0, -1}, -5.0, 5.0), -1.0);
    QCOMPARE(smallestOcticRootInInterval(Octic{1, 0, 0, 0, 0, 0, 0, 0, -1}, -1.0, 5.0), 1.0);
    // (t - 0.25)^2 (t^2 + 1)^3, a double root (a grazing contact) is not lost.
    const Octic tangent{1, -0.5, 3.0625, -1.5, 3.1875, -1.5, 1.1875, -0.5, 0.0625};  // (t - 0.25)^2 (t^2 + 1)^3
    QVERIFY(std::abs(smallestOcticRootInInterval(tangent, 0.0, 1.0) - 0.25) <= 1e-7);
    // Degree four or less: the same as the quartic's.
    QCOMPARE(smallestOcticRootInInterval(Octic{0, 0, 0, 0, 1, -10, 35, -50, 24}, 0.0, 10.0),
             smallestRootInInterval(Quartic{1, -10, 35, -50, 24}, 0.0, 10.0));
    QCOMPARE(smallestOcticRootInInterval(Octic{}, 0.0, 10.0), kInfinity);
}

QTEST_APPLESS_MAIN(TestRootFinders)
#include "tst_rootfinders.moc"
