// Squirt (Alciatore, technical proof A-31): the cue ball leaves off the cue line, away from the side
// of the english, by alpha = atan((5/2) a sqrt(1 - a^2) / (1 + m/me + (5/2)(1 - a^2))). Checked
// against values worked out by hand from the proof's formula, its limits, the sign convention, the
// whole simulation, and bit-identity of shots without an end mass.

#include "CueImpact.h"
#include "SetupFile.h"
#include "Simulation.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace cuelab;

namespace {

constexpr double kR = 0.028575;  // m (WPA)
constexpr double kM = 0.170097;  // kg (WPA)
constexpr double kDeg = 180.0 / std::numbers::pi;

BallState atRest()
{
    BallState s;
    s.position = Vec2(0.5, 0.6);
    return s;
}

}  // namespace

class TestSquirt : public QObject {
    Q_OBJECT
private slots:
    void angle_data();
    void angle();
    void limits();
    void direction();
    void speedAndSpinKept();
    void noEndMassIsBitIdentical();
    void inSimulation();
    void fileKey();
};

// Hand-worked values: with m/me = 30 (pooltool's me = m/30) and a = 0.5,
// alpha = atan(2.5 * 0.5 * 0.8660254 / (31 + 2.5 * 0.75)) = atan(1.0825318 / 32.875) = 1.8860 deg.
// a = 0.25: atan(0.6051536 / 33.34375) = 1.0398 deg; with a light end mass m/me = 20, a = 0.5:
// atan(1.0825318 / 22.875) = 2.7094 deg. TP A-31 quotes squirt of a few degrees for typical cues.
void TestSquirt::angle_data()
{
    QTest::addColumn<double>("side");
    QTest::addColumn<double>("massRatio");
    QTest::addColumn<double>("degrees");
    QTest::newRow("half tip, m/30") << 0.5 << 30.0 << 1.8860;
    QTest::newRow("quarter tip, m/30") << 0.25 << 30.0 << 1.0398;
    QTest::newRow("half tip, m/20") << 0.5 << 20.0 << 2.7094;
    QTest::newRow("left half tip, m/30") << -0.5 << 30.0 << -1.8860;
}

void TestSquirt::angle()
{
    QFETCH(double, side);
    QFETCH(double, massRatio);
    QFETCH(double, degrees);
    const double alpha = squirtAngle(side, kM, kM / massRatio) * kDeg;
    QVERIFY2(std::abs(alpha - degrees) < 5e-4, qPrintable(QString::number(alpha, 'g', 10)));
}

void TestSquirt::limits()
{
    QCOMPARE(squirtAngle(0.0, kM, kM / 30), 0.0);     // centre ball: no squirt
    QCOMPARE(squirtAngle(0.5, kM, 0.0), 0.0);         // no end mass: no squirt
    QVERIFY(std::abs(squirtAngle(1.0, kM, kM / 30)) < 1e-12);  // tip at the edge: sqrt(1 - a^2) = 0
    // A lighter end mass squirts less (low-squirt shafts).
    QVERIFY(squirtAngle(0.5, kM, kM / 40) < squirtAngle(0.5, kM, kM / 20));
    // The maximum over a lies between a = 0 and 1 (about 0.7 for m/me = 30).
    double best = 0.0, bestA = 0.0;
    for (double a = 0.0; a <= 1.0; a += 0.001) {
        const double s = squirtAngle(a, kM, kM / 30);
        if (s > best) best = s, bestA = a;
    }
    QVERIFY(bestA > 0.6 && bestA < 0.8);
}

// Right english (side > 0) sends the ball to the left of the cue line: seen from above, its heading
// turns counter-clockwise; left english turns it clockwise.
void TestSquirt::direction()
{
    for (double heading : {0.0, 37.0, -120.0}) {
        CueStrike strike;
        strike.speed = 2.0;
        strike.headingDeg = heading;
        strike.side = 0.4;
        strike.endMass = kM / 30.0;
        const CueImpactResult r = resolveCueStrike(atRest(), kR, kM, strike);
        const double h = heading / kDeg;
        const Vec2 d(std::cos(h), std::sin(h));
        const double cross = d.x() * r.after.velocity.y() - d.y() * r.after.velocity.x();
        QVERIFY(cross > 0.0);
        const double alpha = std::atan2(cross, d.dot(r.after.velocity));
        QVERIFY(std::abs(alpha - squirtAngle(0.4, kM, kM / 30.0)) < 1e-12);
        QCOMPARE(r.squirt, squirtAngle(0.4, kM, kM / 30.0));
        strike.side = -0.4;
        const CueImpactResult l = resolveCueStrike(atRest(), kR, kM, strike);
        QVERIFY(d.x() * l.after.velocity.y() - d.y() * l.after.velocity.x() < 0.0);
    }
}

void TestSquirt::speedAndSpinKept()
{
    CueStrike strike;
    strike.speed = 3.0;
    strike.side = 0.5;
    strike.height = 0.2;
    const CueImpactResult plain = resolveCueStrike(atRest(), kR, kM, strike);
    strike.endMass = kM / 30.0;
    const CueImpactResult squirted = resolveCueStrike(atRest(), kR, kM, strike);
    QVERIFY(std::abs(plain.after.velocity.norm() - squirted.after.velocity.norm()) < 1e-14);
    QCOMPARE(plain.after.spin, squirted.after.spin);
    QVERIFY(std::abs(plain.impulse.norm() - squirted.impulse.norm()) < 1e-14);
}

void TestSquirt::noEndMassIsBitIdentical()
{
    // Without an end mass (every file written before squirt) the strike is unchanged bit for bit,
    // and a centre-ball hit with an end mass is too.
    CueStrike strike;
    strike.speed = 2.5;
    strike.headingDeg = 12.0;
    strike.side = 0.3;
    strike.height = -0.3;
    const CueImpactResult a = resolveCueStrike(atRest(), kR, kM, strike);
    QCOMPARE(a.squirt, 0.0);
    CueStrike centre = strike;
    centre.side = 0.0;
    const CueImpactResult c0 = resolveCueStrike(atRest(), kR, kM, centre);
    centre.endMass = 0.006;
    const CueImpactResult c1 = resolveCueStrike(atRest(), kR, kM, centre);
    QCOMPARE(c0.after.velocity, c1.after.velocity);
    QCOMPARE(c0.after.spin, c1.after.spin);
}

// In a whole shot the ball's first stretch leaves along the squirted direction.
void TestSquirt::inSimulation()
{
    Setup s;
    s.table.pockets = false;
    Ball cue;
    cue.id = "cue";
    cue.state.position = Vec2(0.5, 0.635);
    s.balls.push_back(cue);
    CueStrike shot;
    shot.ball = "cue";
    shot.speed = 2.0;
    shot.side = 0.5;
    shot.endMass = kM / 30.0;
    s.shot = shot;
    const SimulationResult r = simulate(s);
    QVERIFY(r.events.size() > 1);
    const BallState after = r.events.front().after[0];
    const double alpha = std::atan2(after.velocity.y(), after.velocity.x());
    QVERIFY(std::abs(alpha * kDeg - 1.8860) < 5e-4);
}

void TestSquirt::fileKey()
{
    const QByteArray json = R"({"format": "cuelab-setup", "version": 1, "balls": [{"id": "cue", "position": [1, 0.6]}],
        "shot": {"ball": "cue", "speed": 2, "heading": 0, "elevation": 0, "side": 0.5, "height": 0, "end_mass": 0.0057}})";
    QString error;
    auto s = io::parseSetup(json, QStringLiteral("s.json"), &error);
    QVERIFY2(s, qPrintable(error));
    QCOMPARE(s->shot->endMass, 0.0057);
    const QByteArray saved = io::serializeSetup(*s);
    QVERIFY(saved.contains("\"end_mass\": 0.0057"));
    // Without the key: no squirt, and nothing written.
    QByteArray plain = json;
    plain.replace(", \"end_mass\": 0.0057", "");
    s = io::parseSetup(plain, QStringLiteral("s.json"), &error);
    QVERIFY2(s, qPrintable(error));
    QCOMPARE(s->shot->endMass, 0.0);
    QVERIFY(!io::serializeSetup(*s).contains("end_mass"));
    // Refusals name the field.
    QByteArray bad = json;
    bad.replace("0.0057", "-1");
    QVERIFY(!io::parseSetup(bad, QStringLiteral("s.json"), &error));
    QVERIFY2(error.startsWith(QStringLiteral("s.json: shot.end_mass: must not be negative")), qPrintable(error));
    bad = json;
    bad.replace("0.0057", "\"light\"");
    QVERIFY(!io::parseSetup(bad, QStringLiteral("s.json"), &error));
    QVERIFY2(error.startsWith(QStringLiteral("s.json: shot.end_mass: expected a number")), qPrintable(error));
}

QTEST_APPLESS_MAIN(TestSquirt)
#include "tst_squirt.moc"
