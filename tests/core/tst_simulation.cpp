// The event loop as a whole: the cue strike first, timelines that agree with the event log, the end
// time and the limits, simultaneous events in their documented order, frozen racks and Newton's
// cradle, energy over whole runs.

#include "Racks.h"
#include "Simulation.h"
#include "SimulationChecks.h"

#include <QtTest>

#include <cmath>

using namespace cuelab;
using namespace cuelab::testing;

namespace {

Setup cradleSetup(int count, double speed, double e, BallBallModel model)
{
    Setup s;
    s.table.pockets = false;
    s.physics.ballBallRestitution = e;
    s.physics.ballBallModel = model;
    const Table t = makeTable(s.table);
    s.balls.push_back(ballAt(t, "cue", Vec2(0.5, t.width / 2)));
    for (Ball& b : cradleLine(t, count, Vec2(1.0, t.width / 2))) s.balls.push_back(b);
    CueStrike shot;
    shot.ball = "cue";
    shot.speed = speed;
    s.shot = shot;
    return s;
}

Setup shotSetup(double heading, double side, double height)
{
    Setup s = breakSetup(3.0);
    s.shot->headingDeg = heading;
    s.shot->side = side;
    s.shot->height = height;
    return s;
}

// Every event's agents are in the timelines: the state just after the last event of a ball at an
// instant is what stateAt returns at that instant, and the state before equals the motion up to it.
void verifyTimelines(const SimulationResult& r)
{
    // Continuity (SimulationChecks.h): each segment begins where the previous one's closed-form
    // motion has brought the ball, in velocity too unless a collision or the strike began it.
    const std::string problem = timelineProblem(r);
    QVERIFY2(problem.empty(), problem.c_str());
    // The state just before each event is where the ball's motion brought it.
    for (const Event& e : r.events) {
        if (e.kind == EventKind::CueStrike) continue;
        const BallState before = r.stateAt(e.balls[0], std::nextafter(e.time, -1.0));
        QVERIFY((before.position - e.before[0].position).norm() < 1e-9);
    }
    for (std::size_t i = 1; i < r.events.size(); ++i) QVERIFY(r.events[i - 1].time <= r.events[i].time);
}

}  // namespace

class TestSimulation : public QObject {
    Q_OBJECT
private slots:
    void noShotNoEvents();
    void cueStrikeFirst();
    void timelines_data();
    void timelines();
    void untilLimit();
    void eventLimit();
    void simultaneousOrder();
    void racksAreLegal_data();
    void racksAreLegal();
    void cradle_data();
    void cradle();
    void breakRuns_data();
    void breakRuns();
    void analyticInTheLoop_data();
    void analyticInTheLoop();
};

void TestSimulation::noShotNoEvents()
{
    Setup s = breakSetup(8.0);
    s.shot.reset();
    const SimulationResult r = simulate(s);
    QVERIFY(r.events.empty());
    QVERIFY(r.status == SimulationStatus::AllAtRest);
    QCOMPARE(r.endTime, 0.0);
    QVERIFY(sameState(r.stateAt(3, 5.0), r.balls[3].state));
}

void TestSimulation::cueStrikeFirst()
{
    const SimulationResult r = simulate(breakSetup(8.0));
    QVERIFY(!r.events.empty());
    QVERIFY(r.events[0].kind == EventKind::CueStrike);
    QCOMPARE(r.events[0].time, 0.0);
    QCOMPARE(r.events[0].balls[0], 0);
    QVERIFY(sameState(r.stateAt(0, 0.0), r.events[0].after[0]));
    QVERIFY(sameState(r.events[0].before[0], r.balls[0].state));
    QVERIFY(r.stateAt(0, 0.0).velocity.x() > 7.0);
    QVERIFY(r.status == SimulationStatus::AllAtRest);
    QCOMPARE(r.endTime, r.events.back().time);
    for (int i = 0; i < int(r.balls.size()); ++i) {
        const MotionState m = r.stateAt(i, r.endTime).motion;
        QVERIFY(m == MotionState::Stationary || m == MotionState::Pocketed);
    }
}

void TestSimulation::timelines_data()
{
    QTest::addColumn<double>("heading");
    QTest::addColumn<double>("side");
    QTest::addColumn<double>("height");
    QTest::newRow("break") << 0.0 << 0.0 << 0.0;
    QTest::newRow("cut with english") << 5.0 << 0.5 << 0.2;
    QTest::newRow("draw into the side rail") << 80.0 << -0.2 << -0.6;
    QTest::newRow("back towards the head rail") << 170.0 << 0.0 << 0.3;
}

void TestSimulation::timelines()
{
    QFETCH(double, heading);
    QFETCH(double, side);
    QFETCH(double, height);
    const SimulationResult r = simulate(shotSetup(heading, side, height));
    QVERIFY(r.status == SimulationStatus::AllAtRest);
    verifyTimelines(r);
}

void TestSimulation::untilLimit()
{
    SimulationOptions o;
    o.until = 0.5;
    const SimulationResult r = simulate(breakSetup(8.0), o);
    QVERIFY(r.status == SimulationStatus::ReachedUntil);
    QCOMPARE(r.endTime, 0.5);
    QVERIFY(r.events.back().time <= 0.5);
    // maxTime from the setup limits the same way
    Setup s = breakSetup(8.0);
    s.simulation.maxTime = 0.25;
    const SimulationResult m = simulate(s);
    QVERIFY(m.status == SimulationStatus::ReachedUntil);
    QCOMPARE(m.endTime, 0.25);
    // the full run agrees with the cut one up to the cut
    const SimulationResult full = simulate(breakSetup(8.0));
    for (int i = 0; i < int(full.balls.size()); ++i) QVERIFY(sameState(full.stateAt(i, 0.2), r.stateAt(i, 0.2)));
}

void TestSimulation::eventLimit()
{
    SimulationOptions o;
    o.maxEvents = 20;
    const SimulationResult r = simulate(breakSetup(8.0), o);
    QVERIFY(r.status == SimulationStatus::EventLimit);
    QCOMPARE(r.events.size(), std::size_t(20));
    QVERIFY(!r.error.empty());
    QCOMPARE(r.endTime, r.events.back().time);
}

void TestSimulation::simultaneousOrder()
{
    // Three identical stun balls (indices listed out of place order) end their slides at the same
    // instant, and two mirror-image pairs collide at the same instant: the transitions come first,
    // by ball index, then the collisions by their lower ball index.
    Setup s;
    s.table.pockets = false;
    const Table t = makeTable(s.table);
    s.balls.push_back(ballAt(t, "a", Vec2(0.5, 0.9), Vec2(1, 0)));
    s.balls.push_back(ballAt(t, "b", Vec2(0.5, 0.3), Vec2(1, 0)));
    s.balls.push_back(ballAt(t, "c", Vec2(0.5, 0.6), Vec2(1, 0)));
    const SimulationResult r = simulate(s);
    QVERIFY(r.events.size() >= 3);
    for (int k = 0; k < 3; ++k) {
        QVERIFY(r.events[static_cast<std::size_t>(k)].kind == EventKind::SlideToRoll);
        QCOMPARE(r.events[static_cast<std::size_t>(k)].balls[0], k);
        QCOMPARE(r.events[static_cast<std::size_t>(k)].time, r.events[0].time);
    }

    Setup pairs;
    pairs.table.pockets = false;
    const double y1 = 0.3, y2 = 0.9;
    pairs.balls.push_back(ballAt(t, "p", Vec2(1.5, y2), Vec2(-1, 0)));
    pairs.balls.push_back(ballAt(t, "q", Vec2(1.0, y2), Vec2(1, 0)));
    pairs.balls.push_back(ballAt(t, "r", Vec2(1.5, y1), Vec2(-1, 0)));
    pairs.balls.push_back(ballAt(t, "s", Vec2(1.0, y1), Vec2(1, 0)));
    const SimulationResult q = simulate(pairs);
    std::vector<const Event*> hits;
    for (const Event& e : q.events)
        if (e.kind == EventKind::BallBall) hits.push_back(&e);
    QVERIFY(hits.size() >= 2);
    QCOMPARE(hits[0]->time, hits[1]->time);
    QCOMPARE(hits[0]->balls[0], 0);
    QCOMPARE(hits[0]->balls[1], 1);
    QCOMPARE(hits[1]->balls[0], 2);
    QCOMPARE(hits[1]->balls[1], 3);
}

void TestSimulation::racksAreLegal_data()
{
    QTest::addColumn<int>("kind");
    QTest::newRow("8-ball") << 8;
    QTest::newRow("9-ball") << 9;
    QTest::newRow("cradle line") << 0;
}

void TestSimulation::racksAreLegal()
{
    QFETCH(int, kind);
    const Table t = makeTable(TableKind::Pool9ft);
    const std::vector<Ball> balls = kind == 8 ? rack8Ball(t) : kind == 9 ? rack9Ball(t) : cradleLine(t, 6, Vec2(1, 0.6));
    QCOMPARE(int(balls.size()), kind == 8 ? 15 : kind == 9 ? 9 : 6);
    int touching = 0;
    for (std::size_t i = 0; i < balls.size(); ++i) {
        const Vec2 p = balls[i].state.position;
        QVERIFY(p.x() > t.ballRadius && p.x() < t.length - t.ballRadius && p.y() > t.ballRadius && p.y() < t.width - t.ballRadius);
        for (std::size_t j = i + 1; j < balls.size(); ++j) {
            const double gap = (p - balls[j].state.position).norm() - 2 * t.ballRadius;
            QVERIFY(gap > -1e-12);
            if (gap < 1e-12) ++touching;
            QVERIFY(balls[i].id != balls[j].id);
        }
    }
    QCOMPARE(touching, kind == 8 ? 30 : kind == 9 ? 16 : 5);  // frozen: every neighbour touches
}

void TestSimulation::cradle_data()
{
    QTest::addColumn<int>("count");
    QTest::addColumn<double>("e");
    QTest::addColumn<int>("model");
    QTest::newRow("2 balls, elastic") << 2 << 1.0 << int(BallBallModel::Frictionless);
    QTest::newRow("5 balls, elastic") << 5 << 1.0 << int(BallBallModel::Frictionless);
    QTest::newRow("5 balls, e = 0.95") << 5 << 0.95 << int(BallBallModel::Frictionless);
    QTest::newRow("8 balls, e = 0.9, frictional") << 8 << 0.9 << int(BallBallModel::Frictional);
    QTest::newRow("12 balls, e = 0.5") << 12 << 0.5 << int(BallBallModel::Frictionless);
}

void TestSimulation::cradle()
{
    QFETCH(int, count);
    QFETCH(double, e);
    QFETCH(int, model);
    const SimulationResult r = simulate(cradleSetup(count, 2.0, e, BallBallModel(model)));
    QVERIFY2(r.status == SimulationStatus::AllAtRest, r.error.c_str());
    QVERIFY(r.events.size() < 10000);  // neither hangs nor explodes (a sliding cue ball pushes the line)
    for (const Event& ev : r.events) QVERIFY(maxOverlapAt(r, ev.time) <= 1e-9);
    verifyTimelines(r);
    // Just after the first contact the last ball of the line moves fastest, all along +x.
    const Event* first = nullptr;
    for (const Event& ev : r.events)
        if (ev.kind == EventKind::BallBall) {
            first = &ev;
            break;
        }
    QVERIFY(first);
    const std::vector<BallState> s = r.statesAt(first->time);
    double fastest = 0.0;
    int who = -1;
    for (int i = 0; i < int(s.size()); ++i)
        if (s[static_cast<std::size_t>(i)].velocity.norm() > fastest) {
            fastest = s[static_cast<std::size_t>(i)].velocity.norm();
            who = i;
        }
    // When the instant's collisions are over no pair of the line approaches: the speeds do not fall
    // along it, so the last ball is the fastest (with e = 0.5 the whole line collapses to one speed,
    // held together: then it ties).
    for (int i = 0; i < count; ++i)
        QVERIFY(s[static_cast<std::size_t>(i + 1)].velocity.x() >= s[static_cast<std::size_t>(i)].velocity.x() - 1e-9);
    QVERIFY(s[static_cast<std::size_t>(count)].velocity.norm() >= fastest - 1e-9);
    if (e >= 0.9) QCOMPARE(who, count);
    if (e == 1.0) QVERIFY(std::abs(fastest - first->before[0].velocity.norm()) < 1e-9);
    const double momentumBefore = first->before[0].velocity.x();
    double momentumAfter = 0.0;
    for (const BallState& b : s) momentumAfter += b.velocity.x();
    // Friction between the balls is internal: the frictional law keeps the momentum too.
    QVERIFY(std::abs(momentumAfter - momentumBefore) < 1e-12);
    for (const Event& ev : r.events)
        if (ev.kind == EventKind::BallBall) QVERIFY(momentumChange(r, ev) < 1e-12 * (ev.before[0].velocity.norm() + ev.before[1].velocity.norm()) * r.balls[0].mass + 1e-16);
}

void TestSimulation::breakRuns_data()
{
    QTest::addColumn<double>("speed");
    QTest::addColumn<int>("ballModel");
    QTest::addColumn<int>("cushionModel");
    QTest::newRow("8 m/s") << 8.0 << int(BallBallModel::Frictionless) << int(BallCushionModel::Han2005);
    QTest::newRow("12 m/s, frictional") << 12.0 << int(BallBallModel::Frictional) << int(BallCushionModel::Han2005);
    QTest::newRow("3 m/s, mirror cushions") << 3.0 << int(BallBallModel::Frictionless) << int(BallCushionModel::Mirror);
}

void TestSimulation::breakRuns()
{
    QFETCH(double, speed);
    QFETCH(int, ballModel);
    QFETCH(int, cushionModel);
    Setup s = breakSetup(speed);
    s.physics.ballBallModel = BallBallModel(ballModel);
    s.physics.ballCushionModel = BallCushionModel(cushionModel);
    const SimulationResult r = simulate(s);
    QVERIFY2(r.status == SimulationStatus::AllAtRest, r.error.c_str());
    double energy = totalEnergy(r, r.statesAt(0.0));
    for (const Event& e : r.events) {
        QVERIFY(maxOverlapAt(r, e.time) <= 1e-9);
        for (int k = 0; k < 2; ++k)
            if (e.balls[static_cast<std::size_t>(k)] >= 0)
                QVERIFY(placeProblemAt(r, e.balls[static_cast<std::size_t>(k)], e.time, e.after[static_cast<std::size_t>(k)]).empty());
        if (e.kind == EventKind::BallBall) QVERIFY(momentumChange(r, e) < 1e-12 * 20.0 * r.balls[0].mass);
        // energy never rises, at events and between them
        const double mid = totalEnergy(r, r.statesAt(e.time));
        QVERIFY(mid <= energy * (1 + 1e-12) + 1e-15);
        energy = mid;
        if (e.kind != EventKind::CueStrike) {
            double before = 0.0, after = 0.0;
            for (int k = 0; k < 2; ++k) {
                const int b = e.balls[static_cast<std::size_t>(k)];
                if (b < 0) continue;
                before += kineticEnergy(e.before[static_cast<std::size_t>(k)], r.balls[static_cast<std::size_t>(b)].radius, r.balls[static_cast<std::size_t>(b)].mass);
                after += kineticEnergy(e.after[static_cast<std::size_t>(k)], r.balls[static_cast<std::size_t>(b)].radius, r.balls[static_cast<std::size_t>(b)].mass);
            }
            QVERIFY(after <= before * (1 + 1e-12) + 1e-15);
        }
    }
    verifyTimelines(r);
}

void TestSimulation::analyticInTheLoop_data()
{
    QTest::addColumn<double>("cutDeg");  // angle between the cue ball's path and the line of centres
    QTest::addColumn<double>("k");       // cue ball spin at impact as a multiple of rolling (1 = natural roll)
    QTest::newRow("follow: re-rolls at 2/7") << 0.0 << 1.0;
    QTest::newRow("half-ball 30 deg rule: 33.67 deg") << 30.0 << 1.0;
    QTest::newRow("stun cut: 90 deg rule") << 45.0 << 0.0;
}

void TestSimulation::analyticInTheLoop()
{
    // The analytic results hold inside whole simulations, measured at the collision event and at the
    // cue ball's next slide-to-roll event (e = 1, frictionless balls, a closed table).
    QFETCH(double, cutDeg);
    QFETCH(double, k);
    Setup s;
    s.table.pockets = false;
    s.physics.ballBallRestitution = 1.0;
    s.physics.muRoll = 0.0;  // keeps the cue ball's spin exactly k times rolling up to the impact
    const Table t = makeTable(s.table);
    const double v = 1.0, R = t.ballRadius, phi = cutDeg * M_PI / 180.0;
    const Vec2 object(1.5, 0.6);
    const Vec2 contactCentre = object - 2 * R * Vec2(std::cos(phi), std::sin(phi));
    const Vec2 start = contactCentre - Vec2(0.4, 0.0);
    s.balls.push_back(ballAt(t, "cue", start, Vec2(v, 0), Vec3(0, k * v / R, 0)));
    s.balls.push_back(ballAt(t, "1", object));
    if (k == 0.0) s.physics.muSlide = 0.0;  // a stun ball stays a stun ball up to the impact
    const SimulationResult r = simulate(s);
    const Event* hit = nullptr;
    const Event* reroll = nullptr;
    for (const Event& e : r.events) {
        if (!hit && e.kind == EventKind::BallBall) hit = &e;
        else if (hit && !reroll && e.kind == EventKind::SlideToRoll && e.balls[0] == 0) reroll = &e;
    }
    QVERIFY(hit);
    QVERIFY((hit->before[0].position - contactCentre).norm() < 1e-9);
    if (k == 0.0) {
        const Vec2 a = hit->after[0].velocity, b = hit->after[1].velocity;
        QVERIFY(std::abs(a.dot(b)) < 1e-12 * v * v);  // 90 degrees apart
        return;
    }
    QVERIFY(reroll);
    if (cutDeg == 0.0) {
        QVERIFY((reroll->after[0].velocity - Vec2(2.0 / 7.0 * v, 0)).norm() < 1e-12);
    } else {
        const double out = std::atan2(std::abs(reroll->after[0].velocity.y()), reroll->after[0].velocity.x()) * 180.0 / M_PI;
        QVERIFY2(std::abs(out - 33.67) < 0.01, qPrintable(QString::number(out)));
    }
}

QTEST_APPLESS_MAIN(TestSimulation)
#include "tst_simulation.moc"
