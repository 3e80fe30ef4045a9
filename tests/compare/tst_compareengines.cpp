// The three engines behind one interface: each runs every bundled example, says what it cannot
// represent, and shows the behaviour the 2011 report found (tunnelling, Box2D's lost draw).

#include "CompareFixtures.h"
#include "Divergence.h"
#include "Simulation.h"

#include <QDir>

#include <algorithm>
#include <QtTest>

using namespace cuelab;
using namespace cuelab::compare;
using namespace cuelab::testing;

namespace {

bool mentions(const std::vector<std::string>& warnings, const std::string& text)
{
    for (const std::string& w : warnings)
        if (w.find(text) != std::string::npos) return true;
    return false;
}

EngineSettings engine(EngineKind kind, double dt = 0.0, int substeps = 0)
{
    EngineSettings s;
    s.engine = kind;
    s.dt = dt;
    s.substeps = substeps;
    return s;
}

const Collision* firstBallBall(const EngineRun& r)
{
    for (const Collision& c : r.collisions)
        if (c.kind == CollisionKind::BallBall) return &c;
    return nullptr;
}

bool pocketedIn(const EngineRun& r, const std::string& id, const std::string& pocket)
{
    for (std::size_t i = 0; i < r.ids.size(); ++i)
        if (r.ids[i] == id) return r.finalStates[i] == "pocketed" && r.finalPockets[i] == pocket;
    return false;
}

}  // namespace

class TestCompareEngines : public QObject {
    Q_OBJECT
private slots:
    void everyEngineRunsEveryExample_data();
    void everyEngineRunsEveryExample();
    void exactEngineIsTheSimulator();
    void settingsAndLimits();
    void fastGrazeTunnelsAtSixtyHertz();
    void box2dKeepsMomentumHeadOn();
    void box2dLosesTheDraw();
    void box2dSpeedCapIsAWarning();
    void flyingBallsAreAWarning();
    void cancelling();
};

void TestCompareEngines::everyEngineRunsEveryExample_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("engine");
    const QStringList files = QDir(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples"))
                                  .entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    QVERIFY(files.size() >= 14);
    for (const QString& f : files)
        for (EngineKind k : {EngineKind::Exact, EngineKind::Discrete, EngineKind::Box2D})
            QTest::newRow(qPrintable(f + QLatin1Char(' ') + QString::fromUtf8(toString(k).data()))) << f << int(k);
}

void TestCompareEngines::everyEngineRunsEveryExample()
{
    QFETCH(QString, file);
    QFETCH(int, engine);
    const Setup setup = loadExample(file);
    const Comparison c = compareEngines(setup, ::engine(EngineKind(engine)));
    const EngineRun& r = c.run;
    QVERIFY(r.error.empty());
    QVERIFY(!r.cancelled);
    QVERIFY2(r.atRest, "every example comes to rest under every engine");
    QCOMPARE(r.ids.size(), setup.balls.size());
    QVERIFY(!r.samples.empty());
    for (const auto& k : r.samples) QCOMPARE(k.size(), setup.balls.size());
    QCOMPARE(r.finalStates.size(), setup.balls.size());
    // Every example has a collision, but for the exact engine a ball that flies off the table before
    // meeting anything (off-the-table.json); the discrete method and Box2D cannot fly, so it meets the rail.
    const SimulationResult exact = simulate(setup);
    const bool collides = std::any_of(exact.events.begin(), exact.events.end(), [](const Event& e) { return isCollision(e.kind); });
    QVERIFY(!r.collisions.empty() || (EngineKind(engine) == EngineKind::Exact && !collides));
    for (std::size_t k = 1; k < r.collisions.size(); ++k) QVERIFY(r.collisions[k - 1].time <= r.collisions[k].time);
    for (const Collision& h : r.collisions) {
        QVERIFY(h.ball >= 0 && h.ball < int(setup.balls.size()));
        if (h.kind == CollisionKind::BallBall) QVERIFY(h.other > h.ball);
        else QVERIFY(!h.agent.empty());
    }
    // Every example has a shot: the engines without spin and slide phase must say so.
    if (EngineKind(engine) == EngineKind::Exact) {
        QVERIFY(r.warnings.empty());
        QCOMPARE(c.divergence.maxError, 0.0);
    } else {
        QVERIFY(mentions(r.warnings, "no slide phase"));
        QVERIFY(c.divergence.maxError > 0.0);
        if (setup.shot->height != 0.0) QVERIFY(mentions(r.warnings, "shot.height"));
        if (setup.shot->side != 0.0) QVERIFY(mentions(r.warnings, "shot.side"));
    }
    QCOMPARE(c.divergence.finalError.size(), setup.balls.size());
}

void TestCompareEngines::exactEngineIsTheSimulator()
{
    const Setup setup = loadExample(QStringLiteral("9-ball-break.json"));
    const SimulationResult sim = simulate(setup);
    const EngineRun r = runEngine(setup, engine(EngineKind::Exact));
    int collisions = 0;
    for (const Event& e : sim.events)
        if (isCollision(e.kind) || e.kind == EventKind::BallPocket) ++collisions;
    QCOMPARE(int(r.collisions.size()), collisions);
    QCOMPARE(r.endTime, sim.endTime);
    const std::size_t k = 37;
    for (std::size_t i = 0; i < setup.balls.size(); ++i) {
        const BallState s = sim.stateAt(int(i), r.sampleTime(k));
        if (s.motion != MotionState::Pocketed) QCOMPARE(r.samples[k][i].position, s.position);
    }
}

void TestCompareEngines::settingsAndLimits()
{
    QCOMPARE(resolved(engine(EngineKind::Discrete)).dt, 1.0 / 60.0);
    QCOMPARE(resolved(engine(EngineKind::Discrete)).substeps, 10);
    QCOMPARE(resolved(engine(EngineKind::Box2D)).substeps, 8);
    QVERIFY(!checkSettings(engine(EngineKind::Exact)));
    QVERIFY(!checkSettings(engine(EngineKind::Discrete, 1e-5, 1)));
    QVERIFY(!checkSettings(engine(EngineKind::Box2D, 1e-4, 1)));

    auto problem = checkSettings(engine(EngineKind::Discrete, -0.01));
    QVERIFY(problem);
    QCOMPARE(problem->setting, std::string("dt"));
    problem = checkSettings(engine(EngineKind::Discrete, 1e-6));
    QVERIFY(problem);
    QCOMPARE(problem->setting, std::string("dt"));
    QVERIFY(problem->message.find("1e-05 s") != std::string::npos);
    problem = checkSettings(engine(EngineKind::Box2D, 5e-5));
    QVERIFY(problem);
    QVERIFY(problem->message.find("32-bit floats") != std::string::npos);
    problem = checkSettings(engine(EngineKind::Discrete, 0.01, -1));
    QVERIFY(problem);
    QCOMPARE(problem->setting, std::string("substeps"));
    EngineSettings nan = engine(EngineKind::Box2D, std::nan(""));
    QVERIFY(checkSettings(nan));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, runEngine(Setup{}, engine(EngineKind::Discrete, 1e-7)));

    EngineKind k;
    QVERIFY(parseEngineKind("box2d", k) && k == EngineKind::Box2D);
    QVERIFY(!parseEngineKind("Box2D", k));
}

void TestCompareEngines::fastGrazeTunnelsAtSixtyHertz()
{
    // resources/examples/fast-graze.json: the cue ball at 10 m/s overlaps the 5 by 2 mm.
    const Setup setup = loadExample(QStringLiteral("fast-graze.json"));
    const Comparison exact = compareEngines(setup, engine(EngineKind::Exact));
    const Collision* hit = firstBallBall(exact.exact);
    QVERIFY(hit && exact.exact.collisions.front().kind == CollisionKind::BallBall);
    QVERIFY(pocketedIn(exact.exact, "5", "pocket-t"));

    // 60 Hz, 10 sub-steps: the method never sees the 5 on the way; the first thing it finds is a cushion.
    const Comparison coarse = compareEngines(setup, engine(EngineKind::Discrete, 1.0 / 60.0, 10));
    QVERIFY(!coarse.run.collisions.empty());
    QCOMPARE(int(coarse.run.collisions.front().kind), int(CollisionKind::BallCushion));
    QCOMPARE(coarse.divergence.firstSequenceDifference.value_or(-1), 0);
    QVERIFY(!pocketedIn(coarse.run, "5", "pocket-t"));

    // 1 ms: the hit is found within a sub-step of its time and the 5 drops in the same pocket.
    const Comparison fine = compareEngines(setup, engine(EngineKind::Discrete, 0.001, 10));
    QCOMPARE(int(fine.run.collisions.front().kind), int(CollisionKind::BallBall));
    QVERIFY(!fine.divergence.matched.empty());
    QVERIFY(std::abs(fine.divergence.matched[0].difference()) < 1e-3);
    QVERIFY(fine.divergence.firstSequenceDifference.value_or(0) >= 1);
    QVERIFY(pocketedIn(fine.run, "5", "pocket-t"));

    // Box2D's continuous collision finds it at 60 Hz, but resolves it 1.5 mm deep (3 linear slops
    // at 10 units per metre): the 5 leaves at the wrong angle and misses the pocket.
    const Comparison box = compareEngines(setup, engine(EngineKind::Box2D, 1.0 / 60.0));
    QCOMPARE(int(box.run.collisions.front().kind), int(CollisionKind::BallBall));
    QVERIFY2(box.divergence.worstOverlap > 1e-3, qPrintable(QString::number(box.divergence.worstOverlap)));
    QVERIFY(!pocketedIn(box.run, "5", "pocket-t"));
}

void TestCompareEngines::box2dKeepsMomentumHeadOn()
{
    // Head-on at 2 m/s, restitution 0.95, next to no cloth friction: momentum is kept, and the balls
    // leave with (1 -+ e) / 2 of the speed.
    Setup setup = frictionlessHeadOn(2.0, 0.5);
    setup.physics.ballBallRestitution = 0.95;
    EngineSettings s = engine(EngineKind::Box2D);
    s.sampleDt = 0.01;
    const EngineRun r = runEngine(setup, s);
    const Collision* hit = firstBallBall(r);
    QVERIFY(hit);
    const double contact = (0.5 - 2 * kR) / 2.0;
    QVERIFY(std::abs(hit->time - contact) < r.settings.dt);
    const auto& before = r.samples[std::size_t(contact / s.sampleDt) - 2];
    const auto& after = r.samples[std::size_t(contact / s.sampleDt) + 4];
    const double m = setup.balls[0].mass;
    const Vec2 p0 = m * (before[0].velocity + before[1].velocity);
    const Vec2 p1 = m * (after[0].velocity + after[1].velocity);
    QVERIFY2((p1 - p0).norm() < 1e-5 * p0.norm(), qPrintable(QString::number((p1 - p0).norm() / p0.norm())));
    QVERIFY(std::abs(after[0].velocity.x() - 0.025 * 2.0) < 1e-4);
    QVERIFY(std::abs(after[1].velocity.x() - 0.975 * 2.0) < 1e-4);
    QVERIFY(std::abs(after[1].velocity.y()) < 1e-6);
    // The exact simulator agrees on the speeds, and Box2D's overlap stays within its slop.
    EngineSettings exactSettings = engine(EngineKind::Exact);
    exactSettings.sampleDt = 0.01;
    const EngineRun exact = runEngine(setup, exactSettings);
    QVERIFY(std::abs(exact.samples[std::size_t(contact / 0.01) + 4][1].velocity.x() - 1.95) < 1e-6);
    QVERIFY(r.worstOverlap < 0.002);
}

void TestCompareEngines::box2dLosesTheDraw()
{
    // draw-shot.json: struck below centre, the exact cue ball meets the 1 still spinning backwards
    // and draws back along its path; Box2D has no spin, so its cue ball never comes back.
    const Setup setup = loadExample(QStringLiteral("draw-shot.json"));
    const double heading = setup.shot->headingDeg * M_PI / 180.0;
    const Vec2 d(std::cos(heading), std::sin(heading));
    const auto drawBack = [&](const EngineRun& r) {
        const Collision* hit = firstBallBall(r);
        if (!hit) return 0.0;
        const Vec2 atHit = r.samples[std::size_t(std::ceil(hit->time / r.sampleDt))][0].position;
        return -(r.finalSamples()[0].position - atHit).dot(d);  // > 0: came back towards the player
    };
    const Comparison box = compareEngines(setup, engine(EngineKind::Box2D));
    QVERIFY(mentions(box.run.warnings, "the draw is lost"));
    const double exactBack = drawBack(box.exact);
    const double boxBack = drawBack(box.run);
    QVERIFY2(exactBack > 0.05, qPrintable(QString::number(exactBack)));
    QVERIFY2(boxBack < 0.0, qPrintable(QString::number(boxBack)));
    // ... at any step: it is the model, not the step.
    const Comparison fine = compareEngines(setup, engine(EngineKind::Box2D, 0.001));
    QVERIFY(drawBack(fine.run) < 0.0);
}

void TestCompareEngines::box2dSpeedCapIsAWarning()
{
    // Box2D moves a body at most 2 length units per step: 1.2 m/s at 60 Hz and 100 units per metre.
    const Setup setup = loadExample(QStringLiteral("straight-shot.json"));
    EngineSettings s = engine(EngineKind::Box2D);
    s.lengthScale = 100.0;
    QVERIFY(mentions(runEngine(setup, s).warnings, "above Box2D's limit"));
    QVERIFY(!mentions(runEngine(setup, engine(EngineKind::Box2D)).warnings, "above Box2D's limit"));
}

void TestCompareEngines::flyingBallsAreAWarning()
{
    // A ball given a height and a vertical speed flies in the exact simulator; the two plane engines
    // cannot, and must say so by the ball's id, and so must an elevated cue (no jump).
    Setup setup = loadExample(QStringLiteral("straight-shot.json"));
    Ball& flying = setup.balls.back();
    flying.state.z = 0.02;
    flying.state.vz = 0.5;
    setup.shot->elevationDeg = 30.0;
    QVERIFY(runEngine(setup, engine(EngineKind::Exact)).warnings.empty());
    for (EngineKind k : {EngineKind::Discrete, EngineKind::Box2D}) {
        const std::vector<std::string> w = runEngine(setup, engine(k)).warnings;
        QVERIFY(mentions(w, "balls." + flying.id + ".z 0.02, vz 0.5"));
        QVERIFY(mentions(w, "cannot fly"));
        QVERIFY(mentions(w, "no jump"));
    }
    // On the cloth, no word of flying.
    flying.state.z = 0.0;
    flying.state.vz = 0.0;
    QVERIFY(!mentions(runEngine(setup, engine(EngineKind::Box2D)).warnings, "cannot fly"));
}

void TestCompareEngines::cancelling()
{
    const Setup setup = loadExample(QStringLiteral("8-ball-break.json"));
    int calls = 0;
    const Progress stop = [&](double) { return ++calls < 2; };
    for (EngineKind k : {EngineKind::Discrete, EngineKind::Box2D}) {
        calls = 0;
        const EngineRun r = runEngine(setup, engine(k, 0.001), stop);
        QVERIFY(r.cancelled);
        QCOMPARE(calls, 2);
        QVERIFY(r.endTime < 2.0);
    }
}

QTEST_GUILESS_MAIN(TestCompareEngines)
#include "tst_compareengines.moc"
