// Massé and swerve (issue 23, PHYSICS.md "Airborne balls, jumps and massé"): an elevated cue with a
// side offset spins the ball about a tilted axis, and the cloth's friction along the slip bends the
// sliding path into a parabola that ends when rolling begins. Checked against closed forms:
// - the path while it slides is r0 + v0 t − ½ μ_s g t² û with û the slip's fixed direction;
// - the velocity it rolls away with is v0 − (2/7) u0 (Alciatore TP A.4: friction at the contact
//   point changes v by −P/m and the slip u by −(7/2) P/m, so v − (2/7) u never changes). A bounce's
//   friction acts at the same contact point, so the invariant holds through the jump the strike's
//   vertical part makes: the ball rolls away with the same velocity with or without it;
// - the curve bends towards the side of the english (right english, to the right), as Alciatore's
//   massé shots do, more the steeper the cue.

#include "CueImpact.h"
#include "Motion.h"
#include "Simulation.h"

#include <QtTest>

#include <cmath>

using namespace cuelab;

namespace {

Setup oneBall(double elevation, double side)
{
    Setup s;
    Ball b;
    b.id = "cue";
    b.state.position = Vec2(0.5, 0.635);
    s.balls = {b};
    CueStrike shot;
    shot.ball = "cue";
    shot.speed = 2.0;
    shot.headingDeg = 0.0;
    shot.elevationDeg = elevation;
    shot.side = side;
    shot.height = 0.2;
    s.shot = shot;
    return s;
}

const Event* slideToRoll(const SimulationResult& r)
{
    for (const Event& e : r.events)
        if (e.kind == EventKind::SlideToRoll && e.balls[0] == 0) return &e;
    return nullptr;
}

// The signed angle (rad) from a to b, counter-clockwise positive.
double turn(const Vec2& a, const Vec2& b) { return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)); }

}  // namespace

class TestMasse : public QObject {
    Q_OBJECT
private slots:
    void slidingPathIsAParabola();
    void rollsAwayAlongTheInvariant_data();
    void rollsAwayAlongTheInvariant();
    void curvesTowardsTheEnglish();
};

void TestMasse::slidingPathIsAParabola()
{
    // The level massé (the strike's vertical part dropped): the slide from t = 0 is the whole story.
    const Setup setup = oneBall(70.0, 0.5);
    SimulationOptions level;
    level.strikeKeepsElevation = false;
    const SimulationResult r = simulate(setup, level);
    const BallState s0 = r.events.front().after[0];
    QCOMPARE(int(s0.motion), int(MotionState::Sliding));
    const Event* roll = slideToRoll(r);
    QVERIFY(roll);
    const double R = setup.balls[0].radius, mu = setup.physics.muSlide, g = setup.physics.gravity;
    const Vec2 u0 = slipVelocity(s0, R);
    const Vec2 uhat = u0.normalized();
    // It rolls when the slip, falling at (7/2) μ_s g, is gone.
    QVERIFY(std::abs(roll->time - 2.0 * u0.norm() / (7.0 * mu * g)) < 1e-12);
    for (double f : {0.25, 0.5, 0.75}) {
        const double t = f * roll->time;
        const Vec2 expected = s0.position + s0.velocity * t - 0.5 * mu * g * t * t * uhat;
        QVERIFY2((r.stateAt(0, t).position - expected).norm() < 1e-12,
                 qPrintable(QString::number((r.stateAt(0, t).position - expected).norm())));
    }
}

void TestMasse::rollsAwayAlongTheInvariant_data()
{
    QTest::addColumn<double>("elevation");
    QTest::addColumn<double>("side");
    QTest::addColumn<bool>("vertical");  // the strike keeps its vertical part (it jumps)
    for (bool vertical : {false, true})
        for (double elevation : {0.0, 30.0, 60.0, 80.0})
            for (double side : {-0.5, 0.0, 0.5})
                QTest::addRow("%s %g deg side %g", vertical ? "jump" : "level", elevation, side) << elevation << side << vertical;
}

void TestMasse::rollsAwayAlongTheInvariant()
{
    QFETCH(double, elevation);
    QFETCH(double, side);
    QFETCH(bool, vertical);
    const Setup setup = oneBall(elevation, side);
    SimulationOptions options;
    options.strikeKeepsElevation = vertical;
    const SimulationResult r = simulate(setup, options);
    const BallState s0 = r.events.front().after[0];
    const Vec2 expected = s0.velocity - (2.0 / 7.0) * slipVelocity(s0, setup.balls[0].radius);
    const Event* roll = slideToRoll(r);
    QVERIFY(roll);
    QVERIFY2((roll->after[0].velocity - expected).norm() < 1e-12 * (1.0 + expected.norm()),
             qPrintable(QStringLiteral("%1 against %2").arg(roll->after[0].velocity.x()).arg(expected.x())));
    if (vertical && elevation >= 60.0) {
        bool bounced = false;
        for (const Event& e : r.events) bounced = bounced || e.kind == EventKind::BallTable;
        QVERIFY(bounced);  // the jump happened, and the invariant held through its bounces
    }
}

void TestMasse::curvesTowardsTheEnglish()
{
    double previous = 0.0;
    for (double elevation : {20.0, 45.0, 70.0, 85.0}) {
        const SimulationResult right = simulate(oneBall(elevation, 0.5));
        const SimulationResult left = simulate(oneBall(elevation, -0.5));
        const Vec2 start = right.events.front().after[0].velocity;
        const double bend = turn(start, slideToRoll(right)->after[0].velocity);
        QVERIFY2(bend < 0.0, qPrintable(QString::number(bend)));  // clockwise: to the right
        QVERIFY(std::abs(turn(left.events.front().after[0].velocity, slideToRoll(left)->after[0].velocity) + bend) < 1e-12);
        QVERIFY2(std::abs(bend) > previous, qPrintable(QStringLiteral("%1 deg: %2").arg(elevation).arg(bend)));
        previous = std::abs(bend);
    }
}

QTEST_GUILESS_MAIN(TestMasse)
#include "tst_masse.moc"
