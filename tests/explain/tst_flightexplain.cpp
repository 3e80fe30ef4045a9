// core/explain for balls off the cloth (issue 23): a dropped ball's landing, bounce and the closed-form
// end of its bounces, derived step by step, equal the simulator's events; a ball flown over a rail
// leaves the table. Every figure is checked against the closed forms of PHYSICS.md.

#include "Explain.h"
#include "Frames.h"
#include "FlyingBall.h"
#include "Simulation.h"

#include <QtTest>

#include <cmath>

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

Setup droppedBall(double z0, double vz0)
{
    Setup setup;
    setup.balls = {flyingBall("cue", 0.6, 0.6, z0, vz0)};
    return setup;
}

int firstOf(const SimulationResult& r, EventKind kind, int from = 0)
{
    for (std::size_t k = static_cast<std::size_t>(from); k < r.events.size(); ++k)
        if (r.events[k].kind == kind) return static_cast<int>(k);
    return -1;
}

}  // namespace

class TestFlightExplain : public QObject {
    Q_OBJECT
private slots:
    void landingAndBounce();
    void seriesEnd();
    void offTable();
    void elevatedStrike();
};

void TestFlightExplain::landingAndBounce()
{
    // Thrown up at 0.5 m/s from 3 cm: apex z0 + vz0²/2g, lands at (vz0 + w)/g with w = sqrt(vz0² + 2 g z0),
    // leaves at e_t w; the flights to come sum to 2 e_t w / (g (1 - e_t)).
    const double z0 = 0.03, vz0 = 0.5;
    const Setup setup = droppedBall(z0, vz0);
    const SimulationResult r = simulate(setup);
    const int k = firstOf(r, EventKind::BallTable);
    QVERIFY(k >= 0);
    const Event& ev = r.events[static_cast<std::size_t>(k)];
    const explain::Explanation e = explain::explain(r, k);
    const double g = setup.physics.gravity, et = setup.physics.tableRestitution;
    const double w = std::sqrt(vz0 * vz0 + 2.0 * g * z0);
    QCOMPARE(e.title.english(), std::string("Ball cue lands and bounces on the cloth"));
    QVERIFY(std::abs(resultOf(e, "Why now: the flight lands", "apex") - (z0 + vz0 * vz0 / (2.0 * g))) < 1e-15);
    QVERIFY(std::abs(resultOf(e, "Why now: the flight lands", "t") - ev.time) < 1e-12);
    QVERIFY(std::abs(resultOf(e, "Why now: the flight lands", "w") - w) < 1e-12);
    // The chart's time of impact: the height's quadratic, zero at the chosen root, falling there.
    QVERIFY(e.toi.has_value());
    QVERIFY(std::abs(e.toi->t0 + e.toi->root - ev.time) < 1e-12);
    QVERIFY(std::abs(e.toi->at(0.0) - z0) < 1e-15);
    QVERIFY(std::abs(e.toi->at(e.toi->root)) < 1e-12);
    QVERIFY(std::abs(e.toi->slopeAt(e.toi->root) + w) < 1e-12);
    QCOMPARE(e.toi->roots.size(), std::size_t(2));
    QVERIFY(e.toi->roots.front().tau < 0.0 && e.toi->roots.back().chosen);
    QVERIFY(std::abs(ev.approachSpeed - w) < 1e-12);
    // The energy figure: in flight the cloth takes nothing (the height became speed, m g z0).
    const aim::EnergyParts energy = aim::energyParts(r, k);
    QVERIFY2(std::abs(energy.lostToCloth) < 1e-15, qPrintable(QString::number(energy.lostToCloth)));
    QVERIFY(std::abs(resultOf(e, "The bounce", "vz_after") - et * w) < 1e-12);
    QVERIFY(std::abs(resultOf(e, "The bounce", "Pn") - (1.0 + et) * setup.balls[0].mass * w) < 1e-12);
    QVERIFY(std::abs(resultOf(e, "The next flight", "apex") - et * et * w * w / (2.0 * g)) < 1e-12);
    const double total = 2.0 * et * w / (g * (1.0 - et));
    QVERIFY(std::abs(resultOf(e, "All the bounces to come", "duration") - total) < 1e-12);
    // The ball is on the cloth for good at the predicted end (the series' last event or a later one).
    double settled = -1.0;
    for (const Event& later : r.events)
        if (later.kind == EventKind::BallTable && later.after[0].z == 0.0 && later.after[0].vz == 0.0) settled = later.time;
    QVERIFY(settled > 0.0);
    QVERIFY2(std::abs(settled - (ev.time + total)) < 1e-9, qPrintable(QString::number(settled - (ev.time + total))));
}

void TestFlightExplain::seriesEnd()
{
    // A dropped ball alone on the table: its bounces are summed, and the series' end is explained by
    // T = 2 w e_t / (g (1 - e_t)) from its first landing; the explanation's time is the event's.
    const Setup setup = droppedBall(0.05, 0.0);
    const SimulationResult r = simulate(setup);
    int end = -1;
    for (std::size_t k = 0; k < r.events.size(); ++k)
        if (r.events[k].kind == EventKind::BallTable && r.events[k].before[0].vz == 0.0) end = static_cast<int>(k);
    QVERIFY(end >= 0);
    const explain::Explanation e = explain::explain(r, end);
    QCOMPARE(e.title.english(), std::string("The bounces of ball cue end"));
    QVERIFY(std::abs(resultOf(e, "Why now: the sum of the bounces", "t") - r.events[static_cast<std::size_t>(end)].time) < 1e-12);
    // Against the closed form from the drop itself: it lands at sqrt(2 z0 / g) at w = sqrt(2 g z0),
    // and its bounces last 2 w e / (g (1 - e)) in all.
    const double g = setup.physics.gravity, et = setup.physics.tableRestitution;
    const double w = std::sqrt(2.0 * g * 0.05), landing = std::sqrt(2.0 * 0.05 / g);
    const double total = 2.0 * w * et / (g * (1.0 - et));
    QVERIFY(std::abs(resultOf(e, "Why now: the sum of the bounces", "duration") - total) < 1e-12);
    QVERIFY(std::abs(r.events[static_cast<std::size_t>(end)].time - (landing + total)) < 1e-12);
}

void TestFlightExplain::offTable()
{
    // Thrown hard over the left rail from 10 cm away, 6 cm up and rising: it clears the nose and
    // leaves the table.
    Setup setup = droppedBall(0.06, 1.5);
    setup.balls[0].state.position = Vec2(0.1, 0.6);
    setup.balls[0].state.velocity = Vec2(-3.0, 0.0);
    const SimulationResult r = simulate(setup);
    const int k = firstOf(r, EventKind::BallOffTable);
    QVERIFY(k >= 0);
    const explain::Explanation e = explain::explain(r, k);
    QCOMPARE(e.title.english(), std::string("Ball cue leaves the table"));
    QVERIFY(e.step("Off the table"));
    QVERIFY(e.step("Off the table")->input("z")->value > 0.0);
}

void TestFlightExplain::elevatedStrike()
{
    // A steep, firm stroke with the strike's vertical part kept: the strike's explanation derives the
    // downward velocity -F sin(theta) / m, and the bounce at t = 0 answers it. Without the option the
    // strike has no vertical part and no such step.
    Setup setup = droppedBall(0.0, 0.0);
    setup.balls[0].state.motion = MotionState::Stationary;
    CueStrike shot;
    shot.ball = "cue";
    shot.speed = 4.0;
    shot.headingDeg = 0.0;
    shot.elevationDeg = 60.0;
    shot.height = 0.3;
    setup.shot = shot;
    SimulationOptions options;
    options.strikeKeepsElevation = true;
    const SimulationResult r = simulate(setup, options);
    QVERIFY(r.events.size() >= 2);
    QCOMPARE(int(r.events[1].kind), int(EventKind::BallTable));
    const explain::Explanation strike = explain::explain(r, 0, shot);
    const explain::Step* down = strike.step("The vertical part: into the cloth");
    QVERIFY(down);
    QVERIFY(down->result("vz_after")->value < 0.0);
    QVERIFY(std::abs(down->result("vz_after")->value - r.events[0].after[0].vz) < 1e-12);
    const explain::Explanation bounce = explain::explain(r, 1, shot);
    QCOMPARE(bounce.title.english(), std::string("The cloth answers the elevated cue: ball cue bounces"));
    QVERIFY(std::abs(resultOf(bounce, "Into the cloth", "w") + r.events[0].after[0].vz) < 1e-15);
    QVERIFY(std::abs(resultOf(bounce, "The bounce", "vz_after") - r.events[1].after[0].vz) < 1e-15);
    QVERIFY(r.events[1].after[0].vz > 0.0);  // it jumps

    options.strikeKeepsElevation = false;
    const SimulationResult level = simulate(setup, options);
    QVERIFY(!explain::explain(level, 0, shot).step("The vertical part: into the cloth"));
    // A struck ball already flying (a setup may give it vz) keeps its vz when the strike drops its
    // vertical part: no step says it went into the cloth.
    setup.balls[0] = flyingBall("cue", 0.6, 0.6, 0.01, 0.4);
    const SimulationResult thrown = simulate(setup, options);
    QCOMPARE(thrown.events[0].after[0].vz, 0.4);
    QVERIFY(!explain::explain(thrown, 0, shot).step("The vertical part: into the cloth"));
}

QTEST_GUILESS_MAIN(TestFlightExplain)
#include "tst_flightexplain.moc"
