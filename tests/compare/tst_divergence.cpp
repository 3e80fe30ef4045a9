// Divergence measures on cases computed by hand: synthetic runs, and the 2011 method's known errors
// (a hit found up to one sub-step late, a rolling ball ahead by a t dt / 2).

#include "CompareFixtures.h"
#include "Divergence.h"

#include <QtTest>

using namespace cuelab;
using namespace cuelab::compare;
using namespace cuelab::testing;

namespace {

EngineRun synthetic(std::vector<std::vector<Vec2>> positions, std::vector<Collision> collisions, double overlap)
{
    EngineRun r;
    r.ids = {"a", "b"};
    r.radii = {kR, kR};
    r.sampleDt = 0.5;
    for (const auto& at : positions) {
        std::vector<BallSample> k;
        for (const Vec2& p : at) k.push_back({p, Vec2::Zero(), false});
        r.samples.push_back(k);
    }
    r.collisions = std::move(collisions);
    r.worstOverlap = overlap;
    return r;
}

Collision hit(CollisionKind kind, double t, int ball, int other, const std::string& agent = {})
{
    return {kind, t, ball, other, agent};
}

}  // namespace

class TestDivergence : public QObject {
    Q_OBJECT
private slots:
    void syntheticRuns();
    void identicalRunsDoNotDiverge();
    void discreteHitFoundOneSubStepLate();
    void discreteRollingBallIsAheadByHalfATimesStep();
};

void TestDivergence::syntheticRuns()
{
    // Ball a moves 0.5 m per sample along x in the exact run; the engine's a drifts 1 mm per sample
    // in y and its run ends after two samples, so its last state stands for the third.
    const EngineRun exact = synthetic({{Vec2(0, 0), Vec2(1, 1)}, {Vec2(0.5, 0), Vec2(1, 1)}, {Vec2(1.0, 0), Vec2(1, 1)}},
                                      {hit(CollisionKind::BallBall, 0.3, 0, 1),
                                       hit(CollisionKind::BallCushion, 0.8, 0, -1, "rail-r"),
                                       hit(CollisionKind::BallPocket, 1.2, 1, -1, "pocket-tr")},
                                      0.0);
    const EngineRun engine = synthetic({{Vec2(0, 0), Vec2(1, 1)}, {Vec2(0.5, 0.001), Vec2(1, 1)}},
                                       {hit(CollisionKind::BallBall, 0.32, 0, 1),
                                        hit(CollisionKind::BallCushion, 0.75, 0, -1, "rail-r"),
                                        hit(CollisionKind::BallCushion, 0.9, 0, -1, "rail-t")},
                                       0.003);
    const Divergence d = measureDivergence(exact, engine);
    QCOMPARE(d.times.size(), std::size_t(3));
    QCOMPARE(d.times[2], 1.0);
    QCOMPARE(d.error[0][0], 0.0);
    QVERIFY(std::abs(d.error[0][1] - 0.001) < 1e-15);
    const double last = std::sqrt(0.25 + 1e-6);
    QVERIFY(std::abs(d.error[0][2] - last) < 1e-15);
    QCOMPARE(d.error[1][2], 0.0);
    QVERIFY(std::abs(d.maxError - last) < 1e-15);
    QCOMPARE(d.maxErrorBall, 0);
    QCOMPARE(d.maxErrorTime, 1.0);
    QVERIFY(std::abs(d.finalError[0] - last) < 1e-15);
    QCOMPARE(d.finalError[1], 0.0);
    // The first two collisions match (kind, balls, cushion); the third differs in kind and agent.
    QCOMPARE(d.matched.size(), std::size_t(2));
    QVERIFY(std::abs(d.matched[0].difference() - 0.02) < 1e-15);
    QVERIFY(std::abs(d.matched[1].difference() + 0.05) < 1e-15);
    QVERIFY(std::abs(d.maxEventTimeDifference - 0.05) < 1e-15);
    QVERIFY(d.firstSequenceDifference.has_value());
    QCOMPARE(*d.firstSequenceDifference, 2);
    QCOMPARE(d.worstOverlap, 0.003);

    // A list that is a prefix of the other differs where it ends.
    EngineRun shorter = engine;
    shorter.collisions.resize(1);
    QCOMPARE(measureDivergence(exact, shorter).firstSequenceDifference.value_or(-1), 1);
    // Same pocket, other ball: not the same collision.
    Collision a = hit(CollisionKind::BallPocket, 1.0, 0, -1, "pocket-tr");
    Collision b = a;
    b.ball = 1;
    QVERIFY(!sameCollision(a, b));
    b = a;
    b.agent = "pocket-tl";
    QVERIFY(!sameCollision(a, b));
    QVERIFY(sameCollision(a, a));
}

void TestDivergence::identicalRunsDoNotDiverge()
{
    EngineSettings s;
    s.engine = EngineKind::Exact;
    const Comparison c = compareEngines(loadExample(QStringLiteral("half-ball-cut.json")), s);
    QCOMPARE(c.divergence.maxError, 0.0);
    QVERIFY(!c.divergence.firstSequenceDifference);
    QCOMPARE(c.divergence.matched.size(), c.exact.collisions.size());
    QCOMPARE(c.divergence.maxEventTimeDifference, 0.0);
    QVERIFY(c.run.warnings.empty());
}

void TestDivergence::discreteHitFoundOneSubStepLate()
{
    // Head-on at 3 m/s from 0.5 m: the exact contact is at t* = (0.5 - 2R) / 3. At 60 Hz with 4
    // sub-steps the method tests every 1/240 s and first sees the overlap at 36/240 = 0.15 s, when the
    // cue ball stands at 0.95 m: 2R - 0.05 m = 7.15 mm deep. It then stops there, 7.15 mm behind the
    // exact cue ball, and the 1 leaves 0.15 - t* late, 3 (0.15 - t*) = 7.15 mm behind too.
    const Setup setup = frictionlessHeadOn(3.0, 0.3);
    EngineSettings s;
    s.engine = EngineKind::Discrete;
    s.dt = 1.0 / 60.0;
    s.substeps = 4;
    s.sampleDt = 0.01;
    const Comparison c = compareEngines(setup, s);
    const double tStar = (0.5 - 2 * kR) / 3.0;
    const double depth = 2 * kR - 0.05;
    QVERIFY(!c.run.collisions.empty());
    QCOMPARE(int(c.run.collisions[0].kind), int(CollisionKind::BallBall));
    QVERIFY(std::abs(c.run.collisions[0].time - 0.15) < 1e-12);
    QVERIFY(!c.divergence.matched.empty());
    QVERIFY2(std::abs(c.divergence.matched[0].difference() - (0.15 - tStar)) < 1e-9,
             qPrintable(QString::number(c.divergence.matched[0].difference())));
    QVERIFY2(std::abs(c.divergence.worstOverlap - depth) < 1e-9, qPrintable(QString::number(c.divergence.worstOverlap)));
    QVERIFY2(std::abs(c.divergence.finalError[0] - depth) < 1e-6, qPrintable(QString::number(c.divergence.finalError[0])));
    QVERIFY2(std::abs(c.divergence.finalError[1] - depth) < 1e-6, qPrintable(QString::number(c.divergence.finalError[1])));
    QVERIFY(std::abs(c.divergence.maxError - depth) < 1e-6);
}

void TestDivergence::discreteRollingBallIsAheadByHalfATimesStep()
{
    // A rolling ball: the method moves a whole step at the speed of its start and only then slows
    // it, so after n steps it is ahead of the exact ball by a dt^2 n / 2 = a t dt / 2 (a = mu_roll g).
    const Setup setup = rollingBall(0.6);
    EngineSettings s;
    s.engine = EngineKind::Discrete;
    s.dt = 0.01;
    s.sampleDt = 0.01;
    const Comparison c = compareEngines(setup, s);
    const double a = setup.physics.muRoll * setup.physics.gravity;
    for (int k : {10, 100, 300, 500}) {
        const double t = k * s.dt;
        const double expected = a * t * s.dt / 2.0;
        const double got = c.divergence.error[0][static_cast<std::size_t>(k)];
        QVERIFY2(std::abs(got - expected) < 1e-9, qPrintable(QStringLiteral("t %1: %2 vs %3").arg(t).arg(got).arg(expected)));
    }
    // It is ahead: further along +x than the exact ball.
    QVERIFY(c.run.samples[300][0].position.x() > c.exact.samples[300][0].position.x());
}

QTEST_GUILESS_MAIN(TestDivergence)
#include "tst_divergence.moc"
