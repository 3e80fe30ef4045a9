// The 2011 discrete method: what it gets exactly right, and the flaws it is kept to teach.

#include "DiscreteSimulator.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace cuelab;
using namespace cuelab::discrete;

namespace {

constexpr double R = 0.028575;

Setup closedTable(std::vector<std::pair<Vec2, Vec2>> ballsAt)  // (position, velocity)
{
    Setup s;
    s.table.pockets = false;
    int id = 0;
    for (const auto& [p, v] : ballsAt) {
        Ball b;
        b.id = std::to_string(id++);
        b.state.position = p;
        b.state.velocity = v;
        s.balls.push_back(b);
    }
    return s;
}

DiscreteSettings frictionless()
{
    DiscreteSettings d;
    d.friction = 1e-300;  // effectively none (0 would mean "take mu_roll g from the setup")
    d.restSpeed = 0.0;
    d.maxTime = 2.0;
    return d;
}

const DiscreteEvent* firstOf(const DiscreteResult& r, DiscreteEventKind kind)
{
    for (const DiscreteEvent& e : r.events)
        if (e.kind == kind) return &e;
    return nullptr;
}

}  // namespace

class TestDiscrete : public QObject {
    Q_OBJECT
private slots:
    void rayPlaneTimeOfImpactIsExact_data();
    void rayPlaneTimeOfImpactIsExact();
    void mirrorReflection_data();
    void mirrorReflection();
    void equalMassExchange();
    void tunnellingWithTooFewSubSteps();
    void hitsAreFoundLateWithOverlap();
    void restAndStoppingDistance();
    void pocketing();
};

void TestDiscrete::rayPlaneTimeOfImpactIsExact_data()
{
    QTest::addColumn<double>("speed");
    QTest::addColumn<double>("timeStep");
    QTest::newRow("1 m/s, 60 Hz") << 1.0 << 1.0 / 60;
    QTest::newRow("7 m/s, 60 Hz") << 7.0 << 1.0 / 60;
    QTest::newRow("3 m/s, 10 Hz") << 3.0 << 0.1;
}

void TestDiscrete::rayPlaneTimeOfImpactIsExact()
{
    // Straight motion within a step makes t = N.(X - p0) / N.d exact, whatever the step.
    QFETCH(double, speed);
    QFETCH(double, timeStep);
    const Setup s = closedTable({{Vec2(1.0, 0.6), Vec2(speed, 0.0)}});
    DiscreteSettings d = frictionless();
    d.timeStep = timeStep;
    const DiscreteResult r = simulateDiscrete(s, d);
    const DiscreteEvent* hit = firstOf(r, DiscreteEventKind::BallCushion);
    QVERIFY(hit);
    const double expected = (2.54 - R - 1.0) / speed;
    QVERIFY2(std::abs(hit->time - expected) < 1e-12, qPrintable(QString::number(hit->time - expected)));
}

void TestDiscrete::mirrorReflection_data()
{
    QTest::addColumn<double>("restitution");
    QTest::addColumn<double>("incidenceDeg");
    QTest::newRow("elastic 30°") << 1.0 << 30.0;
    QTest::newRow("elastic 60°") << 1.0 << 60.0;
    QTest::newRow("e 0.85 at 45°") << 0.85 << 45.0;
    QTest::newRow("e 0.5 at 20°") << 0.5 << 20.0;
}

void TestDiscrete::mirrorReflection()
{
    // R = 2(-O.N)N + O with the normal part scaled by e: tan(out) = tan(in) / e.
    QFETCH(double, restitution);
    QFETCH(double, incidenceDeg);
    const double a = incidenceDeg * std::numbers::pi / 180.0;
    Setup s = closedTable({{Vec2(1.27, 0.1), 2.0 * Vec2(std::sin(a), -std::cos(a))}});
    s.physics.cushionRestitution = restitution;
    DiscreteSettings d = frictionless();
    d.maxTime = 0.12;  // only the first hit on the bottom rail
    const DiscreteResult r = simulateDiscrete(s, d);
    QVERIFY(firstOf(r, DiscreteEventKind::BallCushion));
    const Vec2 out = r.frames.back()[0].velocity;
    QVERIFY(out.y() > 0);
    const double outAngle = std::atan2(out.x(), out.y());
    QVERIFY(std::abs(std::tan(outAngle) - std::tan(a) / restitution) < 1e-12);
}

void TestDiscrete::equalMassExchange()
{
    // Head-on, e = 1: the striker stops, the struck ball leaves with its speed (the 2011 report's
    // V1x = U2x, V2x = U1x).
    const Setup s = closedTable({{Vec2(0.5, 0.6), Vec2(2.0, 0.0)}, {Vec2(1.0, 0.6), Vec2::Zero()}});
    DiscreteSettings d = frictionless();
    d.maxTime = 0.3;
    const DiscreteResult r = simulateDiscrete(s, d);
    QVERIFY(firstOf(r, DiscreteEventKind::BallBall));
    QVERIFY(r.frames.back()[0].velocity.norm() < 1e-15);
    QVERIFY(std::abs(r.frames.back()[1].velocity.x() - 2.0) < 1e-15);
}

void TestDiscrete::tunnellingWithTooFewSubSteps()
{
    // A 20 m/s ball grazing another: at 60 Hz a step covers 0.33 m, so one sphere test per step
    // cannot see a contact whose overlap lasts 2.8 mm of travel: the hit is missed.
    const Setup s = closedTable({{Vec2(0.3, 0.6), Vec2(20.0, 0.0)}, {Vec2(0.52, 0.6 + 1.99 * R), Vec2::Zero()}});
    DiscreteSettings coarse = frictionless();
    coarse.subSteps = 1;
    coarse.maxTime = 0.05;
    QVERIFY(!firstOf(simulateDiscrete(s, coarse), DiscreteEventKind::BallBall));

    DiscreteSettings fine = coarse;
    fine.subSteps = 1000;
    QVERIFY(firstOf(simulateDiscrete(s, fine), DiscreteEventKind::BallBall));
}

void TestDiscrete::hitsAreFoundLateWithOverlap()
{
    // Head-on at 3 m/s: the true contact is at t = (0.5 - 2R) / 3. Sub-steps find it up to one
    // sub-step late, with the balls interpenetrating by up to the travel of one sub-step.
    const double speed = 3.0;
    const Setup s = closedTable({{Vec2(0.5, 0.6), Vec2(speed, 0.0)}, {Vec2(1.0, 0.6), Vec2::Zero()}});
    DiscreteSettings d = frictionless();
    d.maxTime = 0.3;
    d.subSteps = 4;
    const DiscreteResult r = simulateDiscrete(s, d);
    const DiscreteEvent* hit = firstOf(r, DiscreteEventKind::BallBall);
    QVERIFY(hit);
    const double exact = (0.5 - 2 * R) / speed;
    const double subStep = d.timeStep / d.subSteps;
    QVERIFY(hit->time >= exact);
    QVERIFY(hit->time < exact + subStep + 1e-12);
    QVERIFY(hit->overlap > 0.0);
    QVERIFY(std::abs(hit->overlap - speed * (hit->time - exact)) < 1e-9);
    QVERIFY(r.maxOverlap > 1e-9);  // far beyond what the exact simulator allows
}

void TestDiscrete::restAndStoppingDistance()
{
    // Constant deceleration a: the ball stops after v^2 / (2a), within one step's travel.
    const double v = 1.5, a = 1.0;
    const Setup s = closedTable({{Vec2(0.2, 0.6), Vec2(v, 0.0)}});
    DiscreteSettings d;
    d.friction = a;
    d.restSpeed = 1e-6;
    d.maxTime = 30.0;
    const DiscreteResult r = simulateDiscrete(s, d);
    QVERIFY(firstOf(r, DiscreteEventKind::Rest));
    const double travelled = r.frames.back()[0].position.x() - 0.2;
    QVERIFY(std::abs(travelled - v * v / (2 * a)) < v * d.timeStep);
    QVERIFY(r.endTime < 30.0);
}

void TestDiscrete::pocketing()
{
    // Straight at the bottom-left corner pocket along the diagonal.
    Setup s = closedTable({{Vec2(0.5, 0.5), Vec2(-1.0, -1.0)}});
    s.table.pockets = true;
    const DiscreteResult r = simulateDiscrete(s, frictionless());
    const DiscreteEvent* drop = firstOf(r, DiscreteEventKind::BallPocket);
    QVERIFY(drop);
    QCOMPARE(makeTable(s.table).pockets[std::size_t(drop->other)].id, std::string("pocket-bl"));
    QVERIFY(r.frames.back()[0].pocketed);
}

QTEST_APPLESS_MAIN(TestDiscrete)
#include "tst_discrete.moc"
