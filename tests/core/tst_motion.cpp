// Closed-form motion between events (PHYSICS.md, "Motion between events") and its analytic results:
// stun to natural roll, stopping time and distance, spin decay, states decided from the numbers.

#include "Motion.h"

#include <QtTest>

#include <cmath>

using namespace cuelab;

namespace {

constexpr double kR = 0.028575;  // m
constexpr double kM = 0.170097;  // kg

BallState moving(double vx, double vy, const Vec3& spin)
{
    BallState s;
    s.position = Vec2(1.0, 0.5);
    s.velocity = Vec2(vx, vy);
    s.spin = spin;
    s.motion = classify(s, kR);
    return s;
}

}  // namespace

class TestMotion : public QObject {
    Q_OBJECT
private slots:
    void stunToNaturalRoll_data();
    void stunToNaturalRoll();
    void rollingStops_data();
    void rollingStops();
    void spinDecay_data();
    void spinDecay();
    void slideEndsAtRest_data();
    void slideEndsAtRest();
    void spinDecaysInEveryState_data();
    void spinDecaysInEveryState();
    void evolveComposes_data();
    void evolveComposes();
    void statesFromNumbers();
    void pathMatchesEvolve();
    void energyFallsBetweenEvents();
};

void TestMotion::stunToNaturalRoll_data()
{
    QTest::addColumn<double>("v0");
    QTest::addColumn<double>("headingDeg");
    QTest::addColumn<double>("muSlide");
    // Golden numbers worked by hand from the textbook results, not from the code: a stun ball
    // (no spin) slides until its slip u0 = v0 is gone, which friction mu g does at rate 7/2 mu g
    // (the slip of a solid sphere: dv/dt = -mu g, R dw/dt = -5/2 mu g), so t = 2 v0 / (7 mu g),
    // it covers v0 t - mu g t^2 / 2 = 12 v0^2 / (49 mu g) and rolls on at 5/7 v0 (Alciatore, "The
    // Illustrated Principles of Pool and Billiards", 2004, and his technical proofs; Marlow, "The
    // Physics of Pocket Billiards", 1995; PHYSICS.md, "Analytic results"). With g = 9.81 m/s^2: 7 mu g = 13.734 (mu 0.2), 10.3005 (0.15),
    // 27.468 (0.4); 49 mu g = 96.138, 72.1035, 192.276.
    QTest::addColumn<double>("time");      // s
    QTest::addColumn<double>("distance");  // m
    QTest::addColumn<double>("speed");     // m/s
    // 1 / 13.734 = 0.0728119994; 3 / 96.138 = 0.0312051426; 5 x 0.5 / 7 = 0.357142857
    QTest::newRow("0.5 m/s along x") << 0.5 << 0.0 << 0.2 << 0.0728119994175 << 0.0312051426075 << 0.357142857143;
    // 2 / 13.734 = 0.145623999; 12 / 96.138 = 0.124820570; 5 / 7 = 0.714285714
    QTest::newRow("1 m/s at 30 deg") << 1.0 << 30.0 << 0.2 << 0.145623998835 << 0.124820570430 << 0.714285714286;
    // 6 / 10.3005 = 0.582495995; 108 / 72.1035 = 1.49784685; 15 / 7 = 2.14285714
    QTest::newRow("3 m/s at 200 deg, mu 0.15") << 3.0 << 200.0 << 0.15 << 0.582495995340 << 1.49784684516 << 2.14285714286;
    // 16 / 27.468 = 0.582495995; 768 / 192.276 = 3.99425825; 40 / 7 = 5.71428571
    QTest::newRow("8 m/s along -y, mu 0.4") << 8.0 << 270.0 << 0.4 << 0.582495995340 << 3.99425825376 << 5.71428571429;
}

void TestMotion::stunToNaturalRoll()
{
    QFETCH(double, v0);
    QFETCH(double, headingDeg);
    QFETCH(double, muSlide);
    QFETCH(double, time);
    QFETCH(double, distance);
    QFETCH(double, speed);
    PhysicsParams p;
    p.muSlide = muSlide;
    QCOMPARE(p.gravity, 9.81);  // the golden numbers assume it
    const double h = headingDeg * M_PI / 180.0;
    const BallState s = moving(v0 * std::cos(h), v0 * std::sin(h), Vec3::Zero());
    QVERIFY(s.motion == MotionState::Sliding);

    const Transition t = nextTransition(s, kR, p);
    QVERIFY(t.kind == EventKind::SlideToRoll);
    const double g = p.gravity;
    // Slides for 2 v0 / (7 mu g) over 12 v0^2 / (49 mu g), then rolls at 5/7 v0.
    QVERIFY(std::abs(t.after - 2.0 * v0 / (7.0 * muSlide * g)) < 1e-14);
    const BallState e = applyTransition(s, kR, p);
    QVERIFY(e.motion == MotionState::Rolling);
    QVERIFY(std::abs((e.position - s.position).norm() - 12.0 * v0 * v0 / (49.0 * muSlide * g)) < 1e-13);
    QVERIFY(std::abs(e.velocity.norm() - 5.0 / 7.0 * v0) < 1e-14);
    QVERIFY(std::abs(e.velocity.normalized().dot(s.velocity.normalized()) - 1.0) < 1e-14);
    QVERIFY(slipVelocity(e, kR).norm() < 1e-15);
    // The hand-worked numbers (12 significant digits).
    QVERIFY2(std::abs(t.after - time) < 1e-11, qPrintable(QString::number(t.after, 'g', 17)));
    QVERIFY2(std::abs((e.position - s.position).norm() - distance) < 1e-11, qPrintable(QString::number((e.position - s.position).norm(), 'g', 17)));
    QVERIFY(std::abs(e.velocity.norm() - speed) < 1e-11);
}

void TestMotion::rollingStops_data()
{
    QTest::addColumn<double>("v0");
    QTest::addColumn<double>("muRoll");
    QTest::addColumn<double>("wz");
    QTest::addColumn<int>("kind");
    QTest::newRow("1 m/s") << 1.0 << 0.01 << 0.0 << int(EventKind::RollToStop);
    QTest::newRow("0.2 m/s, mu 0.005") << 0.2 << 0.005 << 0.0 << int(EventKind::RollToStop);
    QTest::newRow("2 m/s with little side spin") << 2.0 << 0.01 << 5.0 << int(EventKind::RollToStop);
    QTest::newRow("0.3 m/s with strong side spin") << 0.3 << 0.015 << 40.0 << int(EventKind::RollToSpin);
}

void TestMotion::rollingStops()
{
    QFETCH(double, v0);
    QFETCH(double, muRoll);
    QFETCH(double, wz);
    QFETCH(int, kind);
    PhysicsParams p;
    p.muRoll = muRoll;
    const BallState s = moving(0.6 * v0, -0.8 * v0, Vec3(0.8 * v0 / kR, 0.6 * v0 / kR, wz));
    QVERIFY(s.motion == MotionState::Rolling);
    const Transition t = nextTransition(s, kR, p);
    QCOMPARE(int(t.kind), kind);
    // Stops after |v| / (mu_r g) over v^2 / (2 mu_r g).
    QVERIFY(std::abs(t.after - v0 / (muRoll * p.gravity)) < 1e-12);
    const BallState e = applyTransition(s, kR, p);
    QVERIFY(std::abs((e.position - s.position).norm() - v0 * v0 / (2.0 * muRoll * p.gravity)) < 1e-12);
    QVERIFY(e.velocity.isZero(0.0));
    QVERIFY(e.motion == (kind == int(EventKind::RollToSpin) ? MotionState::Spinning : MotionState::Stationary));
    const double alpha = spinDeceleration(p, kR);
    QVERIFY(std::abs(e.spin.z() - std::max(0.0, wz - alpha * t.after)) < 1e-12);
}

void TestMotion::spinDecay_data()
{
    QTest::addColumn<double>("wz");
    QTest::newRow("counter-clockwise 30 rad/s") << 30.0;
    QTest::newRow("clockwise 12 rad/s") << -12.0;
    QTest::newRow("tiny 1e-6 rad/s") << 1e-6;
}

void TestMotion::spinDecay()
{
    QFETCH(double, wz);
    const PhysicsParams p;
    const double alpha = spinDeceleration(p, kR);
    QVERIFY(std::abs(alpha - 10.9) < 0.1);  // pooltool's default, about 10.9 rad/s^2
    BallState s;
    s.spin = Vec3(0, 0, wz);
    s.motion = classify(s, kR);
    QVERIFY(s.motion == MotionState::Spinning);
    const Transition t = nextTransition(s, kR, p);
    QVERIFY(t.kind == EventKind::SpinToStop);
    QVERIFY(std::abs(t.after - std::abs(wz) / alpha) < 1e-15);
    const BallState half = evolve(s, kR, p, t.after / 2);
    QVERIFY(std::abs(half.spin.z() - wz / 2) < 1e-14);
    const BallState e = applyTransition(s, kR, p);
    QVERIFY(e.motion == MotionState::Stationary);
    QVERIFY(e.spin.isZero(0.0));
}

void TestMotion::slideEndsAtRest_data()
{
    QTest::addColumn<double>("wz");
    QTest::addColumn<int>("kind");
    QTest::newRow("draw that cancels the speed") << 0.0 << int(EventKind::SlideToStop);
    QTest::newRow("and side spin left over") << 30.0 << int(EventKind::SlideToSpin);
}

void TestMotion::slideEndsAtRest()
{
    QFETCH(double, wz);
    QFETCH(int, kind);
    const PhysicsParams p;
    // v_end = 5/7 v0 + 2/7 R wy = 0 for wy = -5 v0 / (2 R).
    const double v0 = 1.0;
    const BallState s = moving(v0, 0.0, Vec3(0.0, -2.5 * v0 / kR, wz));
    const Transition t = nextTransition(s, kR, p);
    QCOMPARE(int(t.kind), kind);
    const BallState e = applyTransition(s, kR, p);
    QVERIFY(e.velocity.isZero(0.0));
    QVERIFY(e.motion == (kind == int(EventKind::SlideToSpin) ? MotionState::Spinning : MotionState::Stationary));
}

void TestMotion::spinDecaysInEveryState_data()
{
    QTest::addColumn<double>("vx");
    QTest::addColumn<double>("wy");
    QTest::newRow("sliding") << 2.0 << 0.0;
    QTest::newRow("rolling") << 2.0 << 2.0 / kR;
}

void TestMotion::spinDecaysInEveryState()
{
    QFETCH(double, vx);
    QFETCH(double, wy);
    const PhysicsParams p;
    const BallState s = moving(vx, 0.0, Vec3(0.0, wy, 3.0));
    const double alpha = spinDeceleration(p, kR);
    const double dt = 0.1;
    QVERIFY(dt < nextTransition(s, kR, p).after);
    QVERIFY(std::abs(evolve(s, kR, p, dt).spin.z() - (3.0 - alpha * dt)) < 1e-14);
    // and stays at zero once it got there, while the ball still moves
    const double late = 0.285;
    QVERIFY(late > 3.0 / alpha && late < nextTransition(s, kR, p).after);
    QCOMPARE(evolve(s, kR, p, late).spin.z(), 0.0);
}

void TestMotion::evolveComposes_data()
{
    QTest::addColumn<double>("vx");
    QTest::addColumn<double>("vy");
    QTest::addColumn<double>("wx");
    QTest::addColumn<double>("wy");
    QTest::addColumn<double>("wz");
    QTest::newRow("sliding with side and top spin") << 1.5 << -0.4 << 10.0 << 60.0 << -20.0;
    QTest::newRow("rolling") << 0.7 << 0.7 << -0.7 / kR << 0.7 / kR << 0.0;
    QTest::newRow("massé-like curve") << 0.8 << 0.0 << 80.0 << 0.0 << 0.0;
}

void TestMotion::evolveComposes()
{
    QFETCH(double, vx);
    QFETCH(double, vy);
    QFETCH(double, wx);
    QFETCH(double, wy);
    QFETCH(double, wz);
    const PhysicsParams p;
    const BallState s = moving(vx, vy, Vec3(wx, wy, wz));
    const double d = nextTransition(s, kR, p).after;
    const BallState direct = evolve(s, kR, p, 0.7 * d);
    const BallState twoSteps = evolve(evolve(s, kR, p, 0.3 * d), kR, p, 0.4 * d);
    QVERIFY((direct.position - twoSteps.position).norm() < 1e-13);
    QVERIFY((direct.velocity - twoSteps.velocity).norm() < 1e-13);
    QVERIFY((direct.spin - twoSteps.spin).norm() < 1e-10);
}

void TestMotion::statesFromNumbers()
{
    const PhysicsParams p;
    // Labelled sliding, but the slip is zero: it is rolling, and moves as a rolling ball.
    BallState s = moving(1.0, 0.0, Vec3(0.0, 1.0 / kR, 0.0));
    s.motion = MotionState::Sliding;
    QVERIFY(classify(s, kR) == MotionState::Rolling);
    const Transition t = nextTransition(s, kR, p);
    QVERIFY(t.kind == EventKind::RollToStop);
    QVERIFY(std::abs(t.after - 1.0 / (p.muRoll * p.gravity)) < 1e-12);
    // Labelled stationary while it moves: the numbers decide.
    BallState m = moving(0.5, 0.0, Vec3::Zero());
    m.motion = MotionState::Stationary;
    QVERIFY(evolve(m, kR, p, 0.01).position.x() > m.position.x());
    QVERIFY(classify(BallState{}, kR) == MotionState::Stationary);
}

void TestMotion::pathMatchesEvolve()
{
    const PhysicsParams p;
    const BallState s = moving(1.2, 0.3, Vec3(-5.0, 30.0, 0.0));
    const Path path = pathOf(s, kR, p);
    const double d = nextTransition(s, kR, p).after;
    for (double f : {0.0, 0.25, 0.5, 1.0}) QVERIFY((path.at(f * d) - evolve(s, kR, p, f * d).position).norm() < 1e-14);
}

void TestMotion::energyFallsBetweenEvents()
{
    const PhysicsParams p;
    BallState s = moving(2.0, -1.0, Vec3(40.0, -20.0, 15.0));
    double e0 = kineticEnergy(s, kR, kM);
    for (int k = 0; k < 6 && s.motion != MotionState::Stationary; ++k) {
        const double d = nextTransition(s, kR, p).after;
        for (double f : {0.2, 0.5, 0.9, 1.0}) {
            const double e = kineticEnergy(evolve(s, kR, p, f * d), kR, kM);
            QVERIFY(e <= e0 * (1 + 1e-12));
            e0 = e;
        }
        s = applyTransition(s, kR, p);
    }
    QVERIFY(s.motion == MotionState::Stationary);
}

QTEST_APPLESS_MAIN(TestMotion)
#include "tst_motion.moc"
