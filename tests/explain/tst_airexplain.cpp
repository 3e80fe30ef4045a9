// core/explain for collisions in the air (issue 41): the jump over a ball at 5 m/s, whose cue ball
// meets the 1 on its second hop (event #4), derived in space with the simulator's own law; a ball
// dropped onto a resting one; a ball flown onto a cushion's nose. Each "after" number equals the
// simulator's (ExplainChecks.h), and the figures a reader checks by hand agree with each other.

#include "Explain.h"
#include "ExplainChecks.h"
#include "ExplainText.h"
#include "ExampleSetup.h"
#include "FlyingBall.h"
#include "Simulation.h"

#include <QtTest>

#include <cmath>
#include <cstdlib>

using namespace cuelab;

namespace {

double resultOf(const explain::Explanation& e, const char* step, const char* key)
{
    const explain::Step* s = e.step(step);
    if (!s) qFatal("no step '%s'", step);
    const explain::Quantity* q = s->result(key);
    if (!q) qFatal("no result '%s' in '%s'", key, step);
    return q->value;
}

bool flying(const Event& ev, int k) { return ev.before[static_cast<std::size_t>(k)].motion == MotionState::Airborne; }

int firstAirCollision(const SimulationResult& r, EventKind kind)
{
    for (std::size_t k = 0; k < r.events.size(); ++k)
        if (r.events[k].kind == kind && (flying(r.events[k], 0) || (kind == EventKind::BallBall && flying(r.events[k], 1))))
            return static_cast<int>(k);
    return -1;
}

void dump(const explain::Explanation& e)
{
    if (std::getenv("CUELAB_EXPLAIN_PRINT")) qInfo().noquote() << QString::fromStdString(explain::toMarkdown(e));
}

QStringList check(const SimulationResult& r, const explain::Explanation& e)
{
    QStringList out;
    for (const std::string& p : testing::checkExplanation(r, e)) out << QString::fromStdString(p);
    return out;
}

}  // namespace

class TestAirExplain : public QObject {
    Q_OBJECT
private slots:
    void jumpOntoTheOne();
    void droppedOnARestingBall();
    void ontoTheNose();
    void twoFlyingBalls();
    void frictionInTheAir();
    void intoTheFace();
};

void TestAirExplain::jumpOntoTheOne()
{
    Setup s = loadExample("jump-over-a-ball.json");
    s.shot->speed = 5.0;  // as the lesson suggests: still in the air when it meets the 1
    const SimulationResult r = simulate(s);
    const int k = firstAirCollision(r, EventKind::BallBall);
    QCOMPARE(k, 3);  // event #4
    const Event& ev = r.events[static_cast<std::size_t>(k)];
    const explain::Explanation e = explain::explain(r, k, s.shot);
    dump(e);
    if (std::getenv("CUELAB_EXPLAIN_PRINT_ALL"))
        for (int i = 0; i < static_cast<int>(r.events.size()); ++i) dump(explain::explain(r, i, s.shot));
    const QStringList problems = check(r, e);
    if (!problems.isEmpty()) qWarning().noquote() << problems.join('\n');
    QVERIFY(problems.isEmpty());
    // The normal leaves the cloth's plane: the impulse has a vertical part, the 1 leaves upwards.
    const double nz = resultOf(e, "Contact geometry in space", "n3_z");
    QVERIFY(std::abs(nz) > 0.1);
    QCOMPARE(resultOf(e, "After the collision", "J_z"), ev.impulse.z());
    QVERIFY(std::abs(ev.impulse.z()) > 0.05);
    QCOMPARE(resultOf(e, "After the collision", "v_b_after_z"), ev.after[1].vz);
    QVERIFY(ev.after[1].vz > 0.2);
    // P_n n is the ball-on-ball impulse (the frictionless law has no tangential part): |J| = P_n.
    const double pn = resultOf(e, "Normal impulse", "Pn");
    QVERIFY(std::abs(ev.impulse.norm() - pn) <= 1e-12 * pn);
    // The momentum in space changes only by the cloth's answer (zero here: the 1 is lifted).
    for (const char* axis : {"x", "y", "z"}) {
        const double dP = resultOf(e, "Momentum before and after", (std::string("dP_") + axis).c_str());
        const double cloth = resultOf(e, "Momentum before and after", (std::string("J_cloth_") + axis).c_str());
        QVERIFY2(std::abs(dP - cloth) <= 1e-12 * std::abs(resultOf(e, "Momentum before and after", "P_before_x")) + 1e-15, axis);
    }
    // The text: the flight is a parabola, f is a quartic here (one ball on the cloth), no file names.
    const std::string text = explain::toMarkdown(e);
    QVERIFY(text.find("cue has been in the air") != std::string::npos);
    QVERIFY(text.find("degree 4") != std::string::npos);
    QVERIFY(text.find(".h)") == std::string::npos && text.find(".cpp") == std::string::npos);
    QVERIFY(text.find("e-17") == std::string::npos && text.find("e-16") == std::string::npos);
}

void TestAirExplain::droppedOnARestingBall()
{
    // A ball dropped from 10 cm onto a resting one, 2 cm off its top: the resting ball is driven
    // into the cloth, which answers it (its bounce), and the dropped ball glances off sideways.
    Setup s;
    Ball still;
    still.id = "1";
    still.state.position = Vec2(1.0, 0.6);
    s.balls = {flyingBall("cue", 1.02, 0.6, 0.1, 0.0), still};
    const SimulationResult r = simulate(s);
    const int k = firstAirCollision(r, EventKind::BallBall);
    QVERIFY(k >= 0);
    const explain::Explanation e = explain::explain(r, k);
    dump(e);
    const QStringList problems = check(r, e);
    if (!problems.isEmpty()) qWarning().noquote() << problems.join('\n');
    QVERIFY(problems.isEmpty());
    QVERIFY(e.step("The cloth answers 1"));
    // Two bodies, one on the cloth: f is a quartic; the momentum changes by the cloth's impulse.
    const double clothZ = resultOf(e, "Momentum before and after", "J_cloth_z");
    QVERIFY(clothZ > 0.0);
    QVERIFY(std::abs(resultOf(e, "Momentum before and after", "dP_z") - clothZ) <= 1e-12 * clothZ);
}

void TestAirExplain::ontoTheNose()
{
    // A ball flown at the foot rail 2 cm up, its centre above the nose when it gets there: it meets
    // the nose edge.
    Setup s;
    s.balls = {flyingBall("cue", 2.40, 0.6, 0.02, 0.0, Vec2(3.0, 0.0))};
    const SimulationResult r = simulate(s);
    int k = -1;
    for (EventKind kind : {EventKind::BallCushion, EventKind::BallJaw})
        if (k < 0) k = firstAirCollision(r, kind);
    if (k < 0) QSKIP("the flight meets no cushion in the air (the table's geometry changed)");
    const explain::Explanation e = explain::explain(r, k);
    dump(e);
    const QStringList problems = check(r, e);
    if (!problems.isEmpty()) qWarning().noquote() << problems.join('\n');
    QVERIFY(problems.isEmpty());
    QVERIFY(e.step("The impact"));
}

void TestAirExplain::twoFlyingBalls()
{
    // Two balls thrown at each other 5 cm up, level: the same gravity cancels in c_b − c_a, so f is a
    // quadratic (its quartic and cubic coefficients exactly 0), and the normal is level (n_z = 0).
    Setup s;
    s.balls = {flyingBall("cue", 1.0, 0.6, 0.05, 0.5, Vec2(1.0, 0.0)), flyingBall("1", 1.2, 0.6, 0.05, 0.5, Vec2(-1.0, 0.0))};
    const SimulationResult r = simulate(s);
    const int k = firstAirCollision(r, EventKind::BallBall);
    QVERIFY(k >= 0);
    const explain::Explanation e = explain::explain(r, k);
    dump(e);
    const QStringList problems = check(r, e);
    if (!problems.isEmpty()) qWarning().noquote() << problems.join('\n');
    QVERIFY(problems.isEmpty());
    QVERIFY(e.toi);
    QCOMPARE(int(e.toi->coefficients.size()), 3);
    // Head on: they meet after (0.2 − 2R) / 2 s, each 1 m/s towards the other.
    const double R = r.balls[0].radius;
    QVERIFY(std::abs(e.toi->root - (0.2 - 2.0 * R) / 2.0) <= 1e-12);
    QCOMPARE(resultOf(e, "Contact geometry in space", "n3_z"), 0.0);
    const std::string text = explain::toMarkdown(e);
    QVERIFY(text.find("degree 2") != std::string::npos);
    QVERIFY(text.find("n is level") != std::string::npos);
}

void TestAirExplain::frictionInTheAir()
{
    // The 5 m/s jump with the frictional ball-ball model: the contact points' slip in space and the
    // friction against it are part of the law, and the states after still equal the simulator's.
    Setup s = loadExample("jump-over-a-ball.json");
    s.shot->speed = 5.0;
    s.physics.ballBallModel = BallBallModel::Frictional;
    const SimulationResult r = simulate(s);
    const int k = firstAirCollision(r, EventKind::BallBall);
    QVERIFY(k >= 0);
    const explain::Explanation e = explain::explain(r, k, s.shot);
    dump(e);
    const QStringList problems = check(r, e);
    if (!problems.isEmpty()) qWarning().noquote() << problems.join('\n');
    QVERIFY(problems.isEmpty());
    QVERIFY(e.step("Friction between the balls"));
    const double jt = std::hypot(resultOf(e, "Friction between the balls", "J_t_x"), resultOf(e, "Friction between the balls", "J_t_y"));
    QVERIFY(jt > 0.0);
    // At most μ P_n.
    const explain::Step* friction = e.step("Friction between the balls");
    QVERIFY(jt <= friction->input("mu")->value * resultOf(e, "Normal impulse", "Pn") * (1.0 + 1e-12));
}

void TestAirExplain::intoTheFace()
{
    // A ball hopping 1 cm off the cloth into the foot rail, its centre below the nose: it meets the
    // face, n level.
    Setup s;
    s.balls = {flyingBall("cue", 2.45, 0.6, 0.001, 0.1, Vec2(2.0, 0.0))};
    const SimulationResult r = simulate(s);
    const int k = firstAirCollision(r, EventKind::BallCushion);
    if (k < 0) QSKIP("the hop meets no cushion in the air (the table's geometry changed)");
    const explain::Explanation e = explain::explain(r, k);
    dump(e);
    const QStringList problems = check(r, e);
    if (!problems.isEmpty()) qWarning().noquote() << problems.join('\n');
    QVERIFY(problems.isEmpty());
    QCOMPARE(resultOf(e, "Contact geometry in space", "N3_z"), 0.0);
    QVERIFY(explain::toMarkdown(e).find("face") != std::string::npos);
}

QTEST_GUILESS_MAIN(TestAirExplain)
#include "tst_airexplain.moc"
