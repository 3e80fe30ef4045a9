// Airborne balls (issue 23): flight in closed form, the ball-table impact models and their registry,
// the elevated strike's vertical part, and the bounce series against its closed form and against a
// brute-force sum of its bounces. Expected values are worked by hand in the comments.

#include "BounceSeries.h"
#include "ElevatedStrike.h"
#include "Flight.h"
#include "resolve/FrictionalTable.h"
#include "resolve/FrictionlessTable.h"
#include "resolve/TableModel.h"

#include <QtTest>

#include <cmath>
#include <random>
#include <set>
#include <string>

using namespace cuelab;

namespace {

constexpr double kR = 0.028575;  // m
constexpr double kM = 0.170097;  // kg
constexpr double kG = 9.81;      // m/s^2

AirState ball(const Vec2& v, const Vec3& w, double z, double vz)
{
    BallState s;
    s.position = Vec2(1.0, 0.6);
    s.velocity = v;
    s.spin = w;
    s.motion = classify(s, kR);
    return lifted(s, z, vz);
}

PhysicsParams tableParams(double e, double mu, BallTableModel model = BallTableModel::Frictional)
{
    PhysicsParams p;
    p.tableRestitution = e;
    p.tableFriction = mu;
    p.ballTableModel = model;
    return p;
}

// The series bounce by bounce: the registry's resolver at each landing, Flight.h between them. Stops
// when the rebound speed is below `floor` (or after `cap` bounces).
struct BruteForce {
    double time = 0.0;
    AirState end;
    std::int64_t slipEndsAt = kSlipsThroughout;
    double energyLost = 0.0;
    double worstEnergyRise = 0.0;  // J, the largest rise of the mechanical energy over one bounce
    std::vector<AirState> afterBounces;
};

BruteForce bounceByBounce(const AirState& landing, const PhysicsParams& p, double floor, int cap)
{
    BruteForce b;
    AirState s = landing;
    for (int j = 1; j <= cap; ++j) {
        const double before = mechanicalEnergy(s, kR, kM, kG);
        const TableImpactResult r = resolveTableImpact(s, kR, kM, p);
        const double after = mechanicalEnergy(r.after, kR, kM, kG);
        b.worstEnergyRise = std::max(b.worstEnergyRise, after - before);
        b.energyLost += before - after;
        if (r.slipEnded && b.slipEndsAt == kSlipsThroughout) b.slipEndsAt = j;
        b.afterBounces.push_back(r.after);
        if (r.after.vz < floor) {
            b.end = r.after;
            b.end.vz = 0.0;
            b.end.motion = classify(b.end, kR);  // (r.after was airborne)
            return b;
        }
        const double flight = landingTime(r.after, kG);
        s = fly(r.after, kG, flight);
        s.z = 0.0;  // the landing: z is 0 up to rounding
        b.time += flight;
    }
    b.end = s;
    return b;
}

}  // namespace

class TestAirborne : public QObject {
    Q_OBJECT
private slots:
    void flightTimeAndApex_data();
    void flightTimeAndApex();
    void flightIsUniformAndComposes();
    void tableModelsRegistry();
    void frictionlessBounce();
    void frictionalBounce_data();
    void frictionalBounce();
    void bouncesNeverAddEnergy();
    void levelStrikeStaysOnTheCloth();
    void elevatedStrikeKeepsItsVerticalPart();
    void seriesEndsAtTheClosedForm_data();
    void seriesEndsAtTheClosedForm();
    void seriesMatchesBounceByBounce_data();
    void seriesMatchesBounceByBounce();
    void seriesEnergyIsAccounted();
    void seriesNeverGoesUnderTheCloth();
    void seriesAtABounceIsAfterIt();
    void seriesEdgeRestitutions();
    void seriesTailBoundsTheRest();
    void deterministic();
    void sampleJump();
};

void TestAirborne::flightTimeAndApex_data()
{
    QTest::addColumn<double>("z0");
    QTest::addColumn<double>("vz");
    QTest::addColumn<double>("landing");  // s
    QTest::addColumn<double>("apex");     // m
    // From the cloth: t = 2 vz / g and apex vz^2 / (2 g). vz = 1.962 = g / 5: t = 0.4 s, apex
    // 1.962^2 / 19.62 = 0.1962 m. vz = 4.905 = g / 2: t = 1 s, apex 4.905^2 / 19.62 = 1.22625 m.
    QTest::newRow("g/5 from the cloth") << 0.0 << 1.962 << 0.4 << 0.1962;
    QTest::newRow("g/2 from the cloth") << 0.0 << 4.905 << 1.0 << 1.22625;
    // Dropped from 0.1962 m: t = sqrt(2 z / g) = sqrt(0.04) = 0.2 s.
    QTest::newRow("dropped") << 0.1962 << 0.0 << 0.2 << 0.1962;
    // Thrown down at g/5 from 0.1962 m: w = sqrt(vz^2 + 2 g z) = 1.962 sqrt(2), t = (w - 1.962) / g
    // = 0.2 (sqrt(2) - 1) = 0.0828427125 s.
    QTest::newRow("thrown down") << 0.1962 << -1.962 << 0.2 * (std::sqrt(2.0) - 1.0) << 0.1962;
}

void TestAirborne::flightTimeAndApex()
{
    QFETCH(double, z0);
    QFETCH(double, vz);
    QFETCH(double, landing);
    QFETCH(double, apex);
    const AirState s = ball(Vec2(0.7, -0.2), Vec3(3.0, 1.0, 20.0), z0, vz);
    QVERIFY(isAirborne(s));
    const double t = landingTime(s, kG);
    if (z0 == 0.0) QCOMPARE(t, 2.0 * vz / kG);  // bit for bit, as documented
    QVERIFY2(std::abs(t - landing) <= 1e-15 * landing, qPrintable(QString::number(t - landing)));
    QVERIFY(std::abs(apexHeight(s, kG) - apex) <= 1e-15 * apex);
    const AirState top = fly(s, kG, apexTime(s, kG));
    QVERIFY(std::abs(top.z - apex) <= 1e-15 * apex);
    if (vz > 0.0) QVERIFY(std::abs(top.vz) <= 1e-15 * vz);  // (coming down already: the top is now)
    const AirState down = fly(s, kG, t);
    QVERIFY2(std::abs(down.z) <= 1e-15, qPrintable(QString::number(down.z)));
    QVERIFY(down.vz < 0.0);
    // The vertical speed at landing: sqrt(vz^2 + 2 g z0).
    QVERIFY(std::abs(-down.vz - landingSpeed(s, kG)) <= 1e-14);
    // The centre's path gives the same point as fly() (z measured from the cloth there).
    const SpacePath path = flightPath(s, kR, kG);
    for (double f : {0.1, 0.37, 0.5, 0.93}) {
        const AirState a = fly(s, kG, f * t);
        const Vec3 c = path.at(f * t);
        QVERIFY((c - Vec3(a.position.x(), a.position.y(), kR + a.z)).norm() <= 1e-15);
        QVERIFY(a.z >= 0.0);
    }
}

void TestAirborne::flightIsUniformAndComposes()
{
    const AirState s = ball(Vec2(1.5, 0.5), Vec3(-10.0, 30.0, 5.0), 0.0, 2.0);
    const AirState a = fly(s, kG, 0.3);
    // x = x0 + v t: (1 + 0.45, 0.6 + 0.15); spin and horizontal velocity unchanged.
    QVERIFY((a.position - Vec2(1.45, 0.75)).norm() <= 1e-15);
    QCOMPARE(a.velocity, s.velocity);
    QCOMPARE(a.spin, s.spin);
    // z = 2 (0.3) - 4.905 (0.09) = 0.15855; vz = 2 - 2.943 = -0.943.
    QVERIFY(std::abs(a.z - 0.15855) <= 1e-15);
    QVERIFY(std::abs(a.vz + 0.943) <= 1e-15);
    const AirState b = fly(fly(s, kG, 0.1), kG, 0.2);
    QVERIFY((a.position - b.position).norm() <= 1e-15);
    QVERIFY(std::abs(a.z - b.z) <= 1e-15 && std::abs(a.vz - b.vz) <= 1e-15);
    // Energy is constant in flight.
    QVERIFY(std::abs(mechanicalEnergy(a, kR, kM, kG) - mechanicalEnergy(s, kR, kM, kG)) <= 1e-15);
    // On the cloth and not leaving it: no flight.
    const AirState rest = ball(Vec2(1.0, 0.0), Vec3::Zero(), 0.0, 0.0);
    QVERIFY(!isAirborne(rest));
    QCOMPARE(landingTime(rest, kG), 0.0);
}

void TestAirborne::tableModelsRegistry()
{
    std::set<std::string> names;
    for (BallTableModel m : {BallTableModel::Frictional, BallTableModel::Frictionless}) {
        const TableModelEntry& e = tableModel(m);
        QVERIFY(e.model == m);
        QVERIFY(e.resolve != nullptr);
        QCOMPARE(findTableModel(e.name), &e);
        QVERIFY(toString(m) == e.name);
        names.insert(std::string(e.name));
    }
    QCOMPARE(names.size(), tableModels().size());
    QVERIFY(tableModels().front().model == PhysicsParams{}.ballTableModel);  // the default first
    QVERIFY(findTableModel("bogus") == nullptr);
    QCOMPARE(PhysicsParams{}.tableRestitution, 0.5);
    QCOMPARE(PhysicsParams{}.tableFriction, 0.2);
}

void TestAirborne::frictionlessBounce()
{
    // vz = -2 at e = 0.5: up at 1 m/s, the impulse (1 + e) m 2 = 3 m; nothing horizontal changes.
    const AirState s = ball(Vec2(2.0, 1.0), Vec3(5.0, -7.0, 3.0), 0.0, -2.0);
    const TableImpactResult r = resolveTableImpact(s, kR, kM, tableParams(0.5, 0.2, BallTableModel::Frictionless));
    QCOMPARE(r.after.vz, 1.0);
    QCOMPARE(r.approachSpeed, 2.0);
    QVERIFY(std::abs(r.impulse.z() - 3.0 * kM) <= 1e-15);
    QCOMPARE(r.after.velocity, s.velocity);
    QCOMPARE(r.after.spin, s.spin);
}

void TestAirborne::frictionalBounce_data()
{
    QTest::addColumn<double>("vx");
    QTest::addColumn<double>("vzIn");
    QTest::addColumn<double>("vxOut");
    QTest::addColumn<double>("slipOut");
    QTest::addColumn<bool>("slipEnds");
    // No spin, so the slip is vx. e = 0.5, mu = 0.2: Pn = 1.5 m |vz|, Coulomb limit 0.3 m |vz|, the
    // impulse that ends the slip 2/7 m vx.
    // vx = 1, vz = -2: limit 0.6 m >= 2/7 m: the slip ends, vx' = 5/7, rolling.
    QTest::newRow("slip ends") << 1.0 << -2.0 << 5.0 / 7.0 << 0.0 << true;
    // vx = 3, vz = -0.5: limit 0.15 m < 6/7 m: vx' = 3 - 0.15 = 2.85, slip 3 - 7/2 (0.15) = 2.475.
    QTest::newRow("Coulomb-limited") << 3.0 << -0.5 << 2.85 << 2.475 << false;
}

void TestAirborne::frictionalBounce()
{
    QFETCH(double, vx);
    QFETCH(double, vzIn);
    QFETCH(double, vxOut);
    QFETCH(double, slipOut);
    QFETCH(bool, slipEnds);
    const AirState s = ball(Vec2(vx, 0.0), Vec3(0.0, 0.0, 4.0), 0.0, vzIn);
    FrictionalTableTrace trace;
    const TableImpactResult r = frictionalTable(s, kR, kM, 0.5, 0.2, &trace);
    QCOMPARE(r.slipEnded, slipEnds);
    QVERIFY(std::abs(r.after.vz + 0.5 * vzIn) <= 1e-15);
    QVERIFY(std::abs(r.after.velocity.x() - vxOut) <= 1e-14);
    QCOMPARE(r.after.velocity.y(), 0.0);
    QVERIFY(std::abs(slipVelocity(r.after, kR).x() - slipOut) <= 1e-13);
    QCOMPARE(r.after.spin.z(), 4.0);  // no moment about the vertical
    // It leaves the cloth (vz > 0): airborne; its horizontal numbers roll or slide.
    QVERIFY(r.after.motion == MotionState::Airborne);
    BallState flat = r.after;
    flat.vz = 0.0;
    QVERIFY(classify(flat, kR) == (slipEnds ? MotionState::Rolling : MotionState::Sliding));
    QVERIFY(std::abs(trace.normalImpulse - 1.5 * kM * -vzIn) <= 1e-15);
    // The registry's entry gives the same.
    const TableImpactResult viaRegistry = resolveTableImpact(s, kR, kM, tableParams(0.5, 0.2));
    QCOMPARE(viaRegistry.after.velocity, r.after.velocity);
    QCOMPARE(viaRegistry.after.spin, r.after.spin);
}

void TestAirborne::bouncesNeverAddEnergy()
{
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double worst = 0.0;
    int slipReversed = 0;
    for (int i = 0; i < 20000; ++i) {
        const AirState s = ball(Vec2(4.0 * u(rng), 4.0 * u(rng)), Vec3(200.0 * u(rng), 200.0 * u(rng), 100.0 * u(rng)),
                                0.0, -5.0 * (0.5 * u(rng) + 0.5) - 1e-6);
        const PhysicsParams p = tableParams(0.5 * u(rng) + 0.5, 0.5 * u(rng) + 0.5,
                                            i % 3 == 0 ? BallTableModel::Frictionless : BallTableModel::Frictional);
        const TableImpactResult r = resolveTableImpact(s, kR, kM, p);
        const double before = mechanicalEnergy(s, kR, kM, kG), after = mechanicalEnergy(r.after, kR, kM, kG);
        worst = std::max(worst, (after - before) / before);
        // The slip keeps its direction (rounding aside: a slip that ends is zero to 1e-12 of it).
        const Vec2 u0 = slipVelocity(s, kR);
        if (slipVelocity(r.after, kR).dot(u0) < -1e-12 * u0.squaredNorm()) ++slipReversed;
        QVERIFY(r.after.vz >= 0.0 && r.after.vz <= -s.vz);
    }
    QVERIFY2(worst <= 1e-15, qPrintable(QString::number(worst)));
    QCOMPARE(slipReversed, 0);
}

void TestAirborne::levelStrikeStaysOnTheCloth()
{
    CueStrike strike;
    strike.speed = 3.0;
    strike.headingDeg = 30.0;
    strike.side = 0.3;
    strike.height = 0.2;
    const BallState before = ball(Vec2::Zero(), Vec3::Zero(), 0.0, 0.0);
    const ElevatedStrikeResult r = resolveElevatedStrike(before, kR, kM, strike, PhysicsParams{});
    const CueImpactResult level = resolveCueStrike(before, kR, kM, strike);
    QVERIFY(!r.bounced);
    QCOMPARE(r.after.velocity, level.after.velocity);  // bit for bit the strike of today
    QCOMPARE(r.after.spin, level.after.spin);
    QCOMPARE(r.after.z, 0.0);
    QCOMPARE(r.after.vz, 0.0);
}

void TestAirborne::elevatedStrikeKeepsItsVerticalPart()
{
    // A centre-ball hit (a = b = 0, c = R) at theta: |Q x e| = R sin(theta), so
    // F = 2 V0 / (1/M + (1 + 5/2 sin^2 theta) / m), the ball is driven down at F sin(theta) / m and
    // leaves the cloth at e_table times that. V0 = 5 m/s, theta = 45 degrees, M = 0.567 kg:
    // F = 10 / (1.763668 + 2.25 / 0.170097) = 0.667048 N s; into the cloth at 2.772974 m/s; up at 1.386487.
    CueStrike strike;
    strike.speed = 5.0;
    strike.elevationDeg = 45.0;
    const BallState before = ball(Vec2::Zero(), Vec3::Zero(), 0.0, 0.0);
    const PhysicsParams p;
    const ElevatedStrikeResult r = resolveElevatedStrike(before, kR, kM, strike, p);
    const double F = 2.0 * 5.0 / (1.0 / 0.567 + 2.25 / kM);
    QVERIFY(r.bounced);
    QVERIFY(std::abs(r.vzIntoCloth + F * std::sqrt(0.5) / kM) <= 1e-12);
    QVERIFY(std::abs(r.vzIntoCloth + 2.772974) <= 1e-6);
    QVERIFY(std::abs(r.after.vz - 1.386487) <= 1e-6);
    QVERIFY(isAirborne(r.after));
    // The contact slips backwards hard (the hit is below the cue line's centre: draw), so the bounce is
    // Coulomb-limited: the horizontal speed falls by mu (1 + e) 2.772974 = 0.832 m/s.
    QVERIFY(!r.bounce.slipEnded);
    QVERIFY(std::abs(r.cue.after.velocity.x() - r.after.velocity.x() - 0.2 * 1.5 * 2.772974) <= 1e-6);
    // Energy: the bounce removes energy.
    QVERIFY(mechanicalEnergy(r.after, kR, kM, kG) < mechanicalEnergy(lifted(r.cue.after, 0.0, r.vzIntoCloth), kR, kM, kG));
}

void TestAirborne::seriesEndsAtTheClosedForm_data()
{
    QTest::addColumn<double>("w");
    QTest::addColumn<double>("e");
    QTest::addColumn<double>("duration");
    // T = 2 w e / (g (1 - e)). w = 1.962 (g/5), e = 0.5: 0.4 s. e = 0.8: 4 (0.4) = 1.6 s. e = 0.2:
    // 0.4 / 4 = 0.1 s.
    QTest::newRow("e 0.5") << 1.962 << 0.5 << 0.4;
    QTest::newRow("e 0.8") << 1.962 << 0.8 << 1.6;
    QTest::newRow("e 0.2") << 1.962 << 0.2 << 0.1;
}

void TestAirborne::seriesEndsAtTheClosedForm()
{
    QFETCH(double, w);
    QFETCH(double, e);
    QFETCH(double, duration);
    // Rolling at the contact (u = 0): no friction, so the ball moves on at v the whole time and the
    // series's distance is v T.
    const Vec2 v(1.2, -0.5);
    const AirState landing = ball(v, Vec3(0.5 / kR, 1.2 / kR, 7.0), 0.0, -w);
    const BounceSeries b = bounceSeries(landing, kR, kM, tableParams(e, 0.2));
    QVERIFY2(std::abs(b.duration - duration) <= 1e-15 * duration, qPrintable(QString::number(b.duration - duration)));
    QCOMPARE(b.slipEndsAt, std::int64_t{1});
    QVERIFY((b.displacement - duration * v).norm() <= 1e-15);
    QCOMPARE(b.end.z, 0.0);
    QCOMPARE(b.end.vz, 0.0);
    QCOMPARE(b.end.spin.z(), 7.0);
    QVERIFY(b.end.motion == MotionState::Rolling);
    // Bounce j at T_j = (2 w e / g)(1 - e^(j-1)) / (1 - e): bounce 2 after the first rebound's 2 w e / g.
    QVERIFY(std::abs(bounceTime(b, 2) - 2.0 * w * e / kG) <= 1e-15);
    QVERIFY(std::abs(afterBounce(b, 3).vz - w * e * e * e) <= 1e-15);
}

void TestAirborne::seriesMatchesBounceByBounce_data()
{
    QTest::addColumn<double>("e");
    QTest::addColumn<double>("mu");
    QTest::addColumn<double>("vz");
    QTest::addColumn<Vec2>("v");
    QTest::addColumn<Vec3>("w");
    QTest::addColumn<bool>("slipEnds");
    // Stun ball bouncing: slip 2 m/s; the bounces can take s / (1 - e) = 3.5 (0.2)(1.5)(2) / 0.5 = 4.2.
    QTest::newRow("slip ends") << 0.5 << 0.2 << -2.0 << Vec2(2.0, 0.0) << Vec3(Vec3::Zero()) << true;
    // Slip 4 of the 4.2: e^K <= 1 - 4 / 4.2 = 0.047619, so K = 5 (0.5^4 = 0.0625, 0.5^5 = 0.03125).
    QTest::newRow("slip ends at bounce 5") << 0.5 << 0.2 << -2.0 << Vec2(4.0, 0.0) << Vec3(Vec3::Zero()) << true;
    // A massé's spin: slip |(1, 0) + R (z x w)| far above what the bounces can take (the series's
    // capacity 3.5 (0.2)(1.5)(0.5) / 0.5 = 1.05 m/s).
    QTest::newRow("slips throughout") << 0.5 << 0.2 << -0.5 << Vec2(1.0, 0.3) << Vec3(40.0, 150.0, 20.0) << false;
    QTest::newRow("lively ball") << 0.9 << 0.15 << -1.0 << Vec2(-0.7, 1.1) << Vec3(10.0, -60.0, 0.0) << true;
    QTest::newRow("frictionless cloth") << 0.6 << 0.0 << -1.5 << Vec2(0.4, 0.4) << Vec3(0.0, 80.0, -3.0) << false;
    QTest::newRow("dead cloth") << 0.05 << 0.3 << -3.0 << Vec2(3.0, 0.0) << Vec3(0.0, -100.0, 0.0) << false;
}

void TestAirborne::seriesMatchesBounceByBounce()
{
    QFETCH(double, e);
    QFETCH(double, mu);
    QFETCH(double, vz);
    QFETCH(Vec2, v);
    QFETCH(Vec3, w);
    QFETCH(bool, slipEnds);
    const AirState landing = ball(v, w, 0.0, vz);
    const PhysicsParams p = tableParams(e, mu);
    const BounceSeries series = bounceSeries(landing, kR, kM, p);
    // Bounce by bounce until the rebound is below 1e-300 m/s: e^j w < 1e-300 takes some 7000 bounces
    // at e = 0.9; the rest of the series is then far below rounding.
    const BruteForce brute = bounceByBounce(landing, p, 1e-300, 20000);
    QCOMPARE(series.slipEndsAt != kSlipsThroughout, slipEnds);
    QCOMPARE(series.slipEndsAt, brute.slipEndsAt);
    if (v.x() == 4.0) QCOMPARE(series.slipEndsAt, std::int64_t{5});
    QVERIFY2(std::abs(series.duration - brute.time) <= 1e-13 * series.duration,
             qPrintable(QString("%1 vs %2").arg(series.duration, 0, 'g', 17).arg(brute.time, 0, 'g', 17)));
    QVERIFY2((series.end.position - brute.end.position).norm() <= 1e-12,
             qPrintable(QString::number((series.end.position - brute.end.position).norm())));
    QVERIFY((series.end.velocity - brute.end.velocity).norm() <= 1e-12);
    QVERIFY((series.end.spin - brute.end.spin).norm() <= 1e-9);
    QVERIFY(series.end.motion == brute.end.motion);
    // Each bounce's state in closed form, against the same bounce reached one by one.
    for (std::size_t j = 1; j <= std::min<std::size_t>(60, brute.afterBounces.size()); ++j) {
        const AirState closed = afterBounce(series, static_cast<std::int64_t>(j));
        const AirState& one = brute.afterBounces[j - 1];
        QVERIFY2((closed.position - one.position).norm() <= 1e-12, qPrintable(QString("bounce %1").arg(j)));
        QVERIFY((closed.velocity - one.velocity).norm() <= 1e-12);
        QVERIFY(std::abs(closed.vz - one.vz) <= 1e-15);
    }
    qInfo("e %.2f mu %.2f: T = %.15g s, %.15g s bounce by bounce; slip ends at bounce %lld; distance %.6f m", e, mu,
          series.duration, brute.time, static_cast<long long>(series.slipEndsAt), series.displacement.norm());
}

void TestAirborne::seriesEnergyIsAccounted()
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 300; ++i) {
        const AirState landing = ball(Vec2(3.0 * u(rng), 3.0 * u(rng)), Vec3(100.0 * u(rng), 100.0 * u(rng), 50.0 * u(rng)),
                                      0.0, -0.05 - 3.0 * (0.5 + 0.5 * u(rng)));
        const PhysicsParams p = tableParams(0.45 + 0.45 * u(rng), 0.25 + 0.25 * u(rng));
        const BounceSeries b = bounceSeries(landing, kR, kM, p);
        const double before = mechanicalEnergy(landing, kR, kM, kG), after = mechanicalEnergy(b.end, kR, kM, kG);
        // All of the vertical energy, m w^2 / 2, and a non-negative friction loss.
        QVERIFY(std::abs(b.normalEnergyLost - 0.5 * kM * landing.vz * landing.vz) <= 1e-15);
        QVERIFY(b.frictionEnergyLost >= -1e-15 * before);
        QVERIFY(std::abs(before - after - b.normalEnergyLost - b.frictionEnergyLost) <= 1e-14 * before);
        // The energy falls at every bounce and never rises along the series.
        const BruteForce brute = bounceByBounce(landing, p, 1e-200, 5000);
        QVERIFY(brute.worstEnergyRise <= 1e-15 * before);
        QVERIFY(std::abs(brute.energyLost - (before - after)) <= 1e-12 * before);
        double last = before;
        for (double f : {0.0, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999999, 1.0}) {
            const double energy = mechanicalEnergy(seriesStateAt(b, f * b.duration), kR, kM, kG);
            QVERIFY(energy <= last + 1e-14 * before);
            last = std::min(last, energy);
        }
    }
}

void TestAirborne::seriesNeverGoesUnderTheCloth()
{
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double lowest = 0.0;
    for (int i = 0; i < 200; ++i) {
        const AirState landing = ball(Vec2(2.0 * u(rng) - 1.0, 0.5), Vec3(0.0, 80.0 * u(rng), 0.0), 0.0, -4.0 * u(rng) - 0.01);
        const BounceSeries b = bounceSeries(landing, kR, kM, tableParams(0.95 * u(rng), 0.3 * u(rng)));
        for (int k = 0; k <= 2000; ++k) {
            // Dense near the end, where the bounces crowd: t = T (1 - (k / 2000)^8) runs down to T.
            const double x = 1.0 - static_cast<double>(k) / 2000.0;
            const AirState s = seriesStateAt(b, b.duration * (1.0 - x * x * x * x * x * x * x * x));
            lowest = std::min(lowest, s.z);
        }
        for (std::int64_t j = 1; j < 200; ++j) {
            const AirState a = afterBounce(b, j);
            lowest = std::min(lowest, fly(a, kG, bounceTime(b, j + 1) - bounceTime(b, j)).z);
        }
    }
    QVERIFY2(lowest >= -1e-12, qPrintable(QString::number(lowest)));
}

void TestAirborne::seriesAtABounceIsAfterIt()
{
    // At a bounce's instant (and at the instants around it that round onto it) the series' state is
    // the one after the bounce, as every state at an event's instant: never on the cloth and going
    // into it. With e = 1/2 the series lasts twice its first flight, so its middle is bounce 2's
    // instant (the soak's sample between a landing and the series' end fell there: seed 7, shot 2).
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int checked = 0;
    for (int i = 0; i < 200; ++i) {
        const AirState landing = ball(Vec2(2.0 * u(rng) - 1.0, 0.5), Vec3(0.0, 80.0 * u(rng), 0.0), 0.0, -4.0 * u(rng) - 0.01);
        const BounceSeries b = bounceSeries(landing, kR, kM, tableParams(i % 2 ? 0.5 : 0.95 * u(rng), 0.3 * u(rng)));
        for (std::int64_t j = 2; j < 40; ++j) {
            const double t = bounceTime(b, j);
            for (const double at : {std::nextafter(t, 0.0), t, std::nextafter(t, 1.0)}) {
                const AirState s = seriesStateAt(b, at);
                QVERIFY2(!(s.z <= 0.0 && s.vz < 0.0), qPrintable(QString("bounce %1 at %2: z %3 vz %4").arg(j).arg(at).arg(s.z).arg(s.vz)));
                ++checked;
            }
        }
        if (i % 2) {  // e = 1/2: the middle of the series is bounce 2, left upwards at w e^2
            const AirState mid = seriesStateAt(b, 0.5 * b.duration);
            QCOMPARE(mid.z, 0.0);
            QCOMPARE(mid.vz, afterBounce(b, 2).vz);
        }
    }
    QCOMPARE(checked, 200 * 38 * 3);
}

void TestAirborne::seriesEdgeRestitutions()
{
    const AirState landing = ball(Vec2(1.0, 0.0), Vec3::Zero(), 0.0, -2.0);
    // e = 0: one bounce, no rebound: the series ends where it begins, after bounce 1's friction.
    const BounceSeries dead = bounceSeries(landing, kR, kM, tableParams(0.0, 0.2));
    QCOMPARE(dead.duration, 0.0);
    QCOMPARE(dead.end.position, landing.position);
    // Pn = m 2, limit 0.4 m >= 2/7 m: rolling at 5/7.
    QVERIFY(std::abs(dead.end.velocity.x() - 5.0 / 7.0) <= 1e-15);
    // e = 1: bounces forever.
    const BounceSeries lively = bounceSeries(landing, kR, kM, tableParams(1.0, 0.2));
    QCOMPARE(lively.duration, kNever);
    QVERIFY(std::abs(bounceTime(lively, 3) - 2.0 * 2.0 * 2.0 / kG) <= 1e-15);
    // A ball not coming down: nothing to sum.
    const BounceSeries none = bounceSeries(ball(Vec2(1.0, 0.0), Vec3::Zero(), 0.0, 0.5), kR, kM, PhysicsParams{});
    QCOMPARE(none.duration, 0.0);
}

void TestAirborne::seriesTailBoundsTheRest()
{
    const AirState landing = ball(Vec2(1.5, 0.4), Vec3(20.0, 90.0, 0.0), 0.0, -2.5);
    const BounceSeries b = bounceSeries(landing, kR, kM, tableParams(0.6, 0.2));
    for (std::int64_t j : {1, 2, 5, 12}) {
        const SeriesTail tail = seriesTail(b, j);
        QVERIFY(std::abs(tail.start + tail.duration - b.duration) <= 1e-15);
        for (int k = 0; k <= 500; ++k) {
            const AirState s = seriesStateAt(b, tail.start + tail.duration * k / 500.0);
            QVERIFY(s.z <= tail.maxHeight + 1e-15);
            QVERIFY((s.position - tail.from).norm() <= tail.reach + 1e-15);
        }
    }
}

void TestAirborne::deterministic()
{
    auto run = [] {
        std::mt19937_64 rng(99);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        std::vector<double> out;
        for (int i = 0; i < 100; ++i) {
            const AirState landing = ball(Vec2(u(rng), u(rng)), Vec3(50.0 * u(rng), 50.0 * u(rng), u(rng)), 0.0, -1.0 - u(rng));
            const BounceSeries b = bounceSeries(landing, kR, kM, tableParams(0.5 + 0.4 * u(rng), 0.2));
            const AirState mid = seriesStateAt(b, 0.3 * b.duration);
            out.insert(out.end(), {b.duration, b.end.position.x(), b.end.position.y(), b.end.spin.y(), mid.z, mid.position.x()});
        }
        return out;
    };
    const std::vector<double> first = run(), second = run();
    QCOMPARE(first.size(), second.size());
    QVERIFY(std::memcmp(first.data(), second.data(), first.size() * sizeof(double)) == 0);
}

void TestAirborne::sampleJump()
{
    // The figures docs/airborne.md quotes: V0 = 5 m/s, centre hit, 45 degrees, default cloth.
    CueStrike strike;
    strike.speed = 5.0;
    strike.elevationDeg = 45.0;
    const PhysicsParams p;
    const ElevatedStrikeResult r = resolveElevatedStrike(ball(Vec2::Zero(), Vec3::Zero(), 0.0, 0.0), kR, kM, strike, p);
    const double flight = landingTime(r.after, kG);
    const AirState landing = fly(r.after, kG, flight);
    const BounceSeries b = bounceSeries(landing, kR, kM, p);
    QVERIFY(flight > 0.28 && flight < 0.29);  // 2 (1.386487) / 9.81 = 0.282668 s
    qInfo("jump: up at %.6f m/s, horizontal %.6f m/s; flight %.6f s, apex %.6f m, lands %.6f m away; "
          "the series then lasts %.6f s over %.6f m (slip ends at bounce %lld), ends %s at %.6f m/s",
          r.after.vz, r.after.velocity.norm(), flight, apexHeight(r.after, kG), (landing.position - r.after.position).norm(), b.duration,
          b.displacement.norm(), static_cast<long long>(b.slipEndsAt), toString(b.end.motion).data(), b.end.velocity.norm());
}

QTEST_APPLESS_MAIN(TestAirborne)
#include "tst_airborne.moc"
