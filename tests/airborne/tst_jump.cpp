// Airborne balls in the event loop (issue 23): simulate() flies a ball set up in the air or jumped by
// an elevated strike, lands it (`ball-table`), sums its bounce series in closed form, passes it over
// a ball it clears, hits the one it does not clear, and sends it off the table over a rail. The
// expected values come from the closed forms (Flight.h, BounceSeries.h) and, for the clearance, from
// the flight's envelope sampled independently of the quartic.

#include "BounceSeries.h"
#include "ElevatedStrike.h"
#include "Flight.h"
#include "FlyingBall.h"
#include "Simulation.h"

#include <QtTest>

#include <cmath>

using namespace cuelab;

namespace {

constexpr double kR = 0.028575;  // m (the pool table's ball)
constexpr double kG = 9.81;      // m/s^2

Ball ballAt(const std::string& id, const Vec2& position)
{
    Ball b;
    b.id = id;
    b.state.position = position;
    return b;
}

Setup pool(std::vector<Ball> balls)
{
    Setup s;
    s.balls = std::move(balls);
    for (Ball& b : s.balls) b.state.motion = classify(b.state, b.radius);
    return s;
}

// The jump of tst_airborne::sampleJump: 5 m/s, centre hit, 45 degrees, along +x.
CueStrike jumpShot()
{
    CueStrike strike;
    strike.ball = "cue";
    strike.speed = 5.0;
    strike.elevationDeg = 45.0;
    return strike;
}

std::vector<const Event*> eventsOf(const SimulationResult& r, EventKind kind)
{
    std::vector<const Event*> out;
    for (const Event& e : r.events)
        if (e.kind == kind) out.push_back(&e);
    return out;
}

// simulate() with the elevated strike keeping its vertical part (SimulationOptions).
SimulationResult flying(const Setup& setup)
{
    SimulationOptions options;
    options.strikeKeepsElevation = true;
    return simulate(setup, options);
}

}  // namespace

class TestJump : public QObject {
    Q_OBJECT
private slots:
    void flightTimeAndApex();
    void seriesEndsAtItsClosedForm();
    void energyNeverRises();
    void jumpClearsABallAtAComputedDistance();
    void jumpedOffTheTable();
    void levelStrikeStaysOnTheCloth();
    void deterministic();
};

void TestJump::flightTimeAndApex()
{
    // Thrown up from the cloth at g/5: lands at 2 vz / g = 0.4 s, apex vz^2 / (2 g) = 0.1962 m.
    Ball b = ballAt("cue", Vec2(1.27, 0.635));
    b.state.vz = kG / 5.0;
    const SimulationResult r = flying(pool({b}));
    QVERIFY(r.status == SimulationStatus::AllAtRest);
    const std::vector<const Event*> landings = eventsOf(r, EventKind::BallTable);
    QVERIFY(landings.size() >= 2);  // the landing, and the series' end
    QCOMPARE(landings[0]->time, 2.0 * b.state.vz / kG);  // bit for bit
    QCOMPARE(landings[0]->before[0].vz, -b.state.vz);
    const BallState top = r.stateAt(0, b.state.vz / kG);
    const double apex = b.state.vz * b.state.vz / (2.0 * kG);
    QVERIFY2(std::abs(top.z - apex) <= 1e-15, qPrintable(QString::number(top.z - apex)));
    QVERIFY(top.motion == MotionState::Airborne);
    for (int k = 0; k <= 1000; ++k) QVERIFY(r.stateAt(0, 0.4 * k / 1000.0).z >= -1e-12);
}

void TestJump::seriesEndsAtItsClosedForm()
{
    // Up at 2 m/s from the cloth with a forward slide: lands at 2 vz / g = 0.4077 s at w = 2 m/s;
    // with e = 0.5 the rest of the series lasts 2 w e / (g (1 - e)) = 0.4077 s more, and the landing
    // for good is one `ball-table` event at exactly that time, where BounceSeries puts the ball.
    Ball b = ballAt("cue", Vec2(0.8, 0.635));
    b.state.velocity = Vec2(0.6, 0.0);
    b.state.spin = Vec3(0.0, -5.0, 0.0);
    b.state.vz = 2.0;
    const Setup setup = pool({b});
    const SimulationResult r = flying(setup);
    QVERIFY(r.status == SimulationStatus::AllAtRest);
    const std::vector<const Event*> table = eventsOf(r, EventKind::BallTable);
    QCOMPARE(static_cast<int>(table.size()), 2);
    const double tLand = 2.0 * 2.0 / kG;
    QCOMPARE(table[0]->time, tLand);
    BallState landing = table[0]->before[0];
    const BounceSeries series = bounceSeries(landing, kR, b.mass, setup.physics);
    const double closed = 2.0 * 2.0 * 0.5 / (kG * (1.0 - 0.5));
    QVERIFY(std::abs(series.duration - closed) <= 1e-15);
    QVERIFY2(std::abs(table[1]->time - (tLand + closed)) <= 1e-15,
             qPrintable(QString::number(table[1]->time - (tLand + closed), 'g', 17)));
    const Vec2 end = table[1]->after[0].position;
    QVERIFY2((end - (landing.position + series.displacement)).norm() <= 1e-12,
             qPrintable(QString::number((end - (landing.position + series.displacement)).norm())));
    QCOMPARE(table[1]->after[0].z, 0.0);
    QCOMPARE(table[1]->after[0].vz, 0.0);
    QVERIFY(table[1]->after[0].motion != MotionState::Airborne);
    // Between the landing and the end the ball is at the series' state, never under the cloth.
    for (int k = 0; k <= 2000; ++k) {
        const double t = tLand + closed * k / 2000.0;
        const BallState s = r.stateAt(0, t);
        QVERIFY(s.z >= -1e-12);
        QVERIFY((s.position - seriesStateAt(series, t - tLand).position).norm() <= 1e-12);
    }
    qInfo("series: landing at %.6f s, w = 2 m/s, ends %.6f s later after %.6f m (slip ends at bounce %lld); %zu events",
          tLand, series.duration, series.displacement.norm(), static_cast<long long>(series.slipEndsAt), r.events.size());
}

void TestJump::energyNeverRises()
{
    // A jump (and its bounces, as single events near a ball and then summed) and a ball dropped onto
    // another: the mechanical energy never rises, sampled densely and across every event.
    for (int run = 0; run < 2; ++run) {
        Setup setup;
        if (run == 0) {
            setup = pool({ballAt("cue", Vec2(0.6, 0.635)), ballAt("1", Vec2(0.9, 0.635)), ballAt("2", Vec2(1.2, 0.66))});
            setup.shot = jumpShot();
        } else {
            Ball top = ballAt("a", Vec2(1.27, 0.635));
            top.state.z = 0.2;
            top.state.velocity = Vec2(0.01, 0.0);
            setup = pool({top, ballAt("b", Vec2(1.27 + 0.01, 0.635))});
        }
        const SimulationResult r = flying(setup);
        QVERIFY2(r.status == SimulationStatus::AllAtRest, qPrintable(QString("run %1: status %2 after %3 events: %4").arg(run).arg(int(r.status)).arg(r.events.size()).arg(QString::fromStdString(r.error))));
        std::vector<double> times;
        for (const Event& e : r.events) times.push_back(e.time);
        for (int k = 0; k <= 4000; ++k) times.push_back(r.endTime * k / 4000.0);
        std::sort(times.begin(), times.end());
        // From just after t = 0 (the strike gives the cue its energy there).
        double previous = mechanicalEnergyAt(r, 0.0);
        QVERIFY(previous > 0.0);
        for (double t : times) {
            if (t <= 0.0) continue;
            const double e = mechanicalEnergyAt(r, t);
            QVERIFY2(e <= previous * (1.0 + 1e-12) + 1e-15, qPrintable(QString("rose by %1 J at t = %2").arg(e - previous).arg(t)));
            previous = e;
            for (std::size_t i = 0; i < r.balls.size(); ++i) QVERIFY(r.stateAt(static_cast<int>(i), t).z >= -1e-12);
        }
        QVERIFY(!eventsOf(r, EventKind::BallTable).empty());
    }
}

void TestJump::jumpClearsABallAtAComputedDistance()
{
    // The flight after the strike, as the simulator starts it.
    const PhysicsParams p;
    BallState rest;
    rest.position = Vec2(0.6, 0.635);
    const CueStrike shot = jumpShot();
    const AirState jump = resolveElevatedStrike(rest, kR, 0.170097, shot, p).after;
    const double landing = landingTime(jump, kG);
    const double apex = apexTime(jump, kG);
    // The nearest a resting ball's centre can lie ahead of the cue and be cleared: the maximum over
    // the rising flight of x(s) + sqrt(4R^2 - z(s)^2) (z: the flying centre above the resting one),
    // by dense sampling and golden sections (independent of the quartic).
    auto reach = [&](double s) {
        const AirState a = fly(jump, kG, s);
        return a.z >= 2.0 * kR ? -1e300 : a.position.x() + std::sqrt(4.0 * kR * kR - a.z * a.z);
    };
    double best = 0.0, bestValue = reach(0.0);
    for (int k = 0; k <= 100000; ++k) {
        const double s = apex * k / 100000.0;
        if (reach(s) > bestValue) {
            best = s;
            bestValue = reach(s);
        }
    }
    double a = std::max(0.0, best - apex / 100000.0), b = std::min(apex, best + apex / 100000.0);
    const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int k = 0; k < 200; ++k) {
        const double c = b - phi * (b - a), d = a + phi * (b - a);
        if (reach(c) > reach(d)) b = d;
        else a = c;
    }
    const double clearFrom = reach(0.5 * (a + b));  // absolute x of the obstacle's centre
    auto hitsBeforeLanding = [&](double x) {
        Setup setup = pool({ballAt("cue", rest.position), ballAt("1", Vec2(x, 0.635))});
        setup.shot = shot;
        const SimulationResult r = flying(setup);
        bool hit = false;
        for (const Event& e : r.events) hit = hit || (e.kind == EventKind::BallBall && e.time < landing);
        return hit;
    };
    QVERIFY(!hitsBeforeLanding(clearFrom + 1e-5));
    QVERIFY(!hitsBeforeLanding(clearFrom + 0.1));
    QVERIFY(hitsBeforeLanding(clearFrom - 1e-5));
    QVERIFY(hitsBeforeLanding(clearFrom - 0.01));
    // The cleared ball is passed over: it never moves while the cue flies over it.
    Setup setup = pool({ballAt("cue", rest.position), ballAt("1", Vec2(clearFrom + 0.05, 0.635))});
    setup.shot = shot;
    const SimulationResult r = flying(setup);
    QCOMPARE(r.stateAt(1, landing).position, Vec2(clearFrom + 0.05, 0.635));
    qInfo("the jump clears a resting ball from %.6f m ahead (centre to centre); lands %.6f m ahead at %.6f s; %zu events, "
          "at rest at %.6f s",
          clearFrom - rest.position.x(), fly(jump, kG, landing).position.x() - rest.position.x(), landing, r.events.size(),
          r.endTime);
}

void TestJump::jumpedOffTheTable()
{
    // Jumped towards the foot rail from 0.27 m: at the nose line the ball's bottom is some 9 cm up,
    // far above the rail top (3.66 cm): it leaves the table.
    const Table table = makeTable(TableKind::Pool9ft);
    Setup setup = pool({ballAt("cue", Vec2(table.length - 0.27, table.width / 2.0)), ballAt("1", Vec2(0.5, 0.3))});
    setup.shot = jumpShot();
    const SimulationResult r = flying(setup);
    QVERIFY(r.status == SimulationStatus::AllAtRest);
    const std::vector<const Event*> off = eventsOf(r, EventKind::BallOffTable);
    QCOMPARE(static_cast<int>(off.size()), 1);
    QCOMPARE(off[0]->balls[0], 0);
    QVERIFY(off[0]->before[0].z >= table.cushionHeight);
    QVERIFY(r.stateAt(0, r.endTime + 1.0).motion == MotionState::OffTable);
    QCOMPARE(toString(MotionState::OffTable), std::string_view("off-table"));
    QCOMPARE(toString(EventKind::BallOffTable), std::string_view("ball-off-table"));
    // A soft hop towards the same rail stays on the table (it meets the cushion, or lands short).
    setup.shot->speed = 1.0;
    setup.shot->elevationDeg = 10.0;
    const SimulationResult soft = flying(setup);
    QVERIFY(eventsOf(soft, EventKind::BallOffTable).empty());
    QVERIFY(soft.stateAt(0, soft.endTime).motion != MotionState::OffTable);
}

void TestJump::levelStrikeStaysOnTheCloth()
{
    // Elevation 0: no `ball-table` event, z and vz exactly 0 throughout.
    Setup setup = pool({ballAt("cue", Vec2(0.6, 0.635)), ballAt("1", Vec2(1.2, 0.635))});
    setup.shot = jumpShot();
    setup.shot->elevationDeg = 0.0;
    const SimulationResult r = flying(setup);
    QVERIFY(eventsOf(r, EventKind::BallTable).empty());
    // With the option off (SimulationOptions::strikeKeepsElevation) an elevated strike is taken
    // level, as before issue 23; by default it jumps.
    Setup steep = setup;
    steep.shot->elevationDeg = 45.0;
    SimulationOptions level;
    level.strikeKeepsElevation = false;
    QVERIFY(eventsOf(simulate(steep, level), EventKind::BallTable).empty());
    QVERIFY(!eventsOf(simulate(steep), EventKind::BallTable).empty());
    for (const Event& e : r.events)
        for (const BallState& s : {e.before[0], e.after[0], e.before[1], e.after[1]}) {
            QCOMPARE(s.z, 0.0);
            QCOMPARE(s.vz, 0.0);
        }
}

void TestJump::deterministic()
{
    Setup setup = pool({ballAt("cue", Vec2(0.6, 0.635)), ballAt("1", Vec2(0.75, 0.64)), ballAt("2", Vec2(1.3, 0.6))});
    setup.shot = jumpShot();
    const SimulationResult a = flying(setup);
    const SimulationResult b = flying(setup);
    QCOMPARE(a.events.size(), b.events.size());
    for (std::size_t k = 0; k < a.events.size(); ++k) {
        QCOMPARE(a.events[k].time, b.events[k].time);
        QVERIFY(a.events[k].kind == b.events[k].kind);
        QCOMPARE(a.events[k].after[0].position, b.events[k].after[0].position);
        QCOMPARE(a.events[k].after[0].z, b.events[k].after[0].z);
        QCOMPARE(a.events[k].after[0].vz, b.events[k].after[0].vz);
    }
}

QTEST_APPLESS_MAIN(TestJump)
#include "tst_jump.moc"
