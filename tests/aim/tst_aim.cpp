// The aiming geometry (core/aim/Aim.h) against hand-worked cases, the heading for a chosen cut, and
// the first contact of the bundled examples; the same functions feed the Shot dock, the Inspector, the
// view's ghost ball and `cuelab-cli explain`'s cut_angle and ball_fraction.

#include "Aim.h"
#include "Explain.h"
#include "SetupFile.h"
#include "ExampleSetup.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace cuelab;
Q_DECLARE_METATYPE(cuelab::Vec2)

namespace {

constexpr double R = 0.028575;  // m, a pool ball
constexpr double D = 2 * R;     // m, centres at contact

Setup example(const QString& name) { return loadExample(name); }

double rad(double deg) { return deg * std::numbers::pi / 180.0; }

}  // namespace

class TestAim : public QObject {
    Q_OBJECT
private slots:
    // The object ball's centre D from the ghost ball at an angle φ to the path (+x): the cut is φ,
    // the fraction 1 − sin φ worked by hand (sin 30° = ½, sin 0 = 0, sin 90° = 1, sin 45° = 0.7071068).
    void handWorked_data()
    {
        QTest::addColumn<double>("bearing");   // degrees of n from the path, counter-clockwise
        QTest::addColumn<double>("cut");
        QTest::addColumn<double>("fraction");
        QTest::addColumn<int>("side");
        QTest::newRow("full hit") << 0.0 << 0.0 << 1.0 << int(aim::CutSide::Straight);
        QTest::newRow("half ball, left") << 30.0 << 30.0 << 0.5 << int(aim::CutSide::Left);
        QTest::newRow("half ball, right") << -30.0 << 30.0 << 0.5 << int(aim::CutSide::Right);
        QTest::newRow("45 degrees") << 45.0 << 45.0 << 1.0 - 0.70710678118654752 << int(aim::CutSide::Left);
        QTest::newRow("graze") << -90.0 << 90.0 << 0.0 << int(aim::CutSide::Right);
    }
    void handWorked()
    {
        QFETCH(double, bearing);
        QFETCH(double, cut);
        QFETCH(double, fraction);
        QFETCH(int, side);
        const Vec2 ghost(1.0, 0.5);
        const Vec2 object = ghost + D * Vec2(std::cos(rad(bearing)), std::sin(rad(bearing)));
        const aim::AimGeometry g = aim::geometryAt(ghost, Vec2(2.0, 0.0), object, R, R, Vec2(0.3, 0.5));
        QVERIFY2(std::abs(g.cutAngleDeg - cut) < 1e-12, qPrintable(QString::number(g.cutAngleDeg, 'g', 17)));
        QVERIFY2(std::abs(g.ballFraction - fraction) < 1e-12, qPrintable(QString::number(g.ballFraction, 'g', 17)));
        QCOMPARE(int(g.side), side);
        // The contact lies R from both centres, on the line of centres.
        QVERIFY(std::abs((g.contactPoint - ghost).norm() - R) < 1e-15);
        QVERIFY(std::abs((g.contactPoint - object).norm() - R) < 1e-15);
        QVERIFY(std::abs(g.contactOnStruckDeg - bearing) < 1e-12);
        QVERIFY(std::abs(std::abs(g.contactOnObjectDeg - g.contactOnStruckDeg) - 180.0) < 1e-12);
        QCOMPARE(g.aimStart, Vec2(0.3, 0.5));
    }

    // C = (0.5, 0.5), O = (1.5, 0.5): a half-ball cut to the left passes D sin 30° = R = 0.028575 m
    // right of O, so the heading is −asin(0.028575 / 1) = −1.6374497891449°; to the right +1.63745°.
    // C = (0, 0), O = (0.6, 0.8) (|O − C| = 1, bearing 53.130102354156°): 45° to the left is
    // 53.130102354156 − asin(0.05715 · 0.70710678 / 1) = 53.130102354156 − 2.3160191448466°.
    void headingForCut_data()
    {
        QTest::addColumn<Vec2>("from");
        QTest::addColumn<Vec2>("object");
        QTest::addColumn<double>("cut");
        QTest::addColumn<int>("side");
        QTest::addColumn<double>("heading");
        QTest::newRow("half ball left") << Vec2(0.5, 0.5) << Vec2(1.5, 0.5) << 30.0 << int(aim::CutSide::Left) << -1.6374497891449091;
        QTest::newRow("half ball right") << Vec2(0.5, 0.5) << Vec2(1.5, 0.5) << 30.0 << int(aim::CutSide::Right) << 1.6374497891449091;
        QTest::newRow("straight") << Vec2(0.5, 0.5) << Vec2(1.5, 0.5) << 0.0 << int(aim::CutSide::Straight) << 0.0;
        QTest::newRow("45 left, oblique") << Vec2(0.0, 0.0) << Vec2(0.6, 0.8) << 45.0 << int(aim::CutSide::Left)
                                          << 53.13010235415599 - 2.3160191448465812;
    }
    void headingForCut()
    {
        QFETCH(Vec2, from);
        QFETCH(Vec2, object);
        QFETCH(double, cut);
        QFETCH(int, side);
        QFETCH(double, heading);
        const std::optional<double> h = aim::headingForCut(from, object, R, R, cut, aim::CutSide(side));
        QVERIFY(h);
        QVERIFY2(std::abs(*h - heading) < 1e-10, qPrintable(QString::number(*h, 'g', 17)));
        // Back again: the straight path along that heading makes that cut.
        const std::optional<aim::AimGeometry> g = aim::plannedContact(from, *h, object, R, R);
        QVERIFY(g);
        QVERIFY2(std::abs(g->cutAngleDeg - cut) < 1e-9, qPrintable(QString::number(g->cutAngleDeg, 'g', 17)));
        if (cut > 0.0) QCOMPARE(int(g->side), side);
        QVERIFY(std::abs((g->objectBall - g->ghostBall).norm() - D) < 1e-12);
    }

    void impossibleAims()
    {
        // Touching (here overlapping) balls have no path to a contact; cuts of 90° and more are no hit.
        QVERIFY(!aim::headingForCut(Vec2(0.5, 0.5), Vec2(0.5 + 0.99 * D, 0.5), R, R, 10.0, aim::CutSide::Left));
        QVERIFY(!aim::headingForCut(Vec2(0.5, 0.5), Vec2(1.5, 0.5), R, R, 90.0, aim::CutSide::Left));
        QVERIFY(!aim::headingForCut(Vec2(0.5, 0.5), Vec2(1.5, 0.5), R, R, -1.0, aim::CutSide::Left));
        // A path pointing away, or passing more than D from the object ball, misses.
        QVERIFY(!aim::plannedContact(Vec2(0.5, 0.5), 180.0, Vec2(1.5, 0.5), R, R));
        QVERIFY(!aim::plannedContact(Vec2(0.5, 0.5), 10.0, Vec2(1.5, 0.5), R, R));
    }

    // The bundled examples are set up as their names say: the half-ball cut's first contact is 30°
    // and a half ball; the straight shot's is (nearly) full. Explain's geometry step reports the same
    // numbers as core/aim (the contract's cut_angle and ball_fraction).
    void examples_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<double>("cut");
        QTest::addColumn<double>("fraction");
        QTest::addColumn<double>("tolerance");
        QTest::newRow("half-ball cut") << "half-ball-cut.json" << 30.0 << 0.5 << 1e-3;
        QTest::newRow("straight shot") << "straight-shot.json" << 0.0 << 1.0 << 0.5;
    }
    void examples()
    {
        QFETCH(QString, file);
        QFETCH(double, cut);
        QFETCH(double, fraction);
        QFETCH(double, tolerance);
        const Setup s = example(file);
        const SimulationResult r = simulate(s);
        int index = -1, object = -1;
        const std::optional<aim::AimGeometry> g = aim::firstContact(r, &index, &object);
        QVERIFY(g);
        QVERIFY2(std::abs(g->cutAngleDeg - cut) < tolerance, qPrintable(QString::number(g->cutAngleDeg, 'g', 17)));
        QVERIFY(std::abs(g->ballFraction - fraction) < tolerance);
        QCOMPARE(r.balls[std::size_t(object)].id, std::string("1"));
        // The ghost ball is the struck ball's centre at the contact; the aim line starts at its place.
        QCOMPARE(g->ghostBall, r.events[std::size_t(index)].before[0].position);
        QCOMPARE(g->aimStart, r.balls[std::size_t(r.events[0].balls[0])].state.position);
        const explain::Explanation e = explain::explain(r, index, s.shot);
        const explain::Step* geometry = e.step("Contact geometry");
        QVERIFY(geometry);
        QVERIFY(geometry->result("cut_angle"));
        QCOMPARE(geometry->result("cut_angle")->value, g->cutAngleDeg);
        QCOMPARE(geometry->result("ball_fraction")->value, g->ballFraction);
    }

    // The launch: the struck ball's state just after the strike; a centre-ball strike of a level cue
    // gives no spin, a strike above centre gives topspin (Alciatore A-30: ω = 5 v b / (2 R) … > 0).
    void launch()
    {
        Setup s = example("straight-shot.json");
        SimulationResult r = simulate(s);
        std::optional<aim::Launch> l = aim::launchOf(r);
        QVERIFY(l);
        QCOMPARE(l->velocity, r.events[0].after[0].velocity);
        QVERIFY(l->speed > s.shot->speed);  // v = 2 V0 / (1 + m/M) > V0 for a heavier cue
        QVERIFY(std::abs(l->topspin) < 1e-9);
        s.shot->height = 0.4;
        r = simulate(s);
        l = aim::launchOf(r);
        QVERIFY(l && l->topspin > 1.0);
        s.shot.reset();
        QVERIFY(!aim::launchOf(simulate(s)));
    }
};

QTEST_GUILESS_MAIN(TestAim)
#include "tst_aim.moc"
