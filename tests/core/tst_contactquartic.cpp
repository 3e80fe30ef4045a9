// The quartic of two balls' contact, |dr(t)|^2 - (2R)^2 = 0, as the simulator builds it: contact
// times against the geometry solved in binary128, thousands of exactly grazing contacts (a double
// root that rounding may lift or split) never missed, and a search restarted from a grazing contact
// moving on to the next touch. The solver's own accuracy: tst_quartic.

#include "QuarticReference.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <random>

using namespace cuelab;
using namespace cuelab::quartictest;

namespace {

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

class TestContactQuartic : public QObject {
    Q_OBJECT
private slots:
    void ballBallContact_data();
    void ballBallContact();
    void grazingContactsAreNeverMissed();
    void grazingContactRestartMovesOn();
};

// Two balls whose relative position is quadratic in t (sliding or rolling with friction); the
// contact time is the smallest root of |dr(t)|^2 - (2R)^2. The reference solves the geometry in
// binary128 from a starting guess. Grazing rows touch exactly once (a double root); rounding the
// coefficients may push the exact polynomial's minimum a hair either side of zero, and the solver
// must still report the touch, to within the sqrt(eps) conditioning of a double root.
void TestContactQuartic::ballBallContact_data()
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

void TestContactQuartic::ballBallContact()
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
void TestContactQuartic::grazingContactsAreNeverMissed()
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
void TestContactQuartic::grazingContactRestartMovesOn()
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


QTEST_APPLESS_MAIN(TestContactQuartic)
#include "tst_contactquartic.moc"
