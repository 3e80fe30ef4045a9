// Values beyond real play but within the safe bounds (core/setup/RealPlay.h, CONTRACT.md Extensions
// version 2): the setup is legal, and setupWarnings names each such value once, with its path, the
// ball's id and the real-play limit; values at the limit, and values refused anyway, are not warned.

#include "LegalSetup.h"
#include "RealPlay.h"

#include <QtTest>

#include <functional>

using namespace cuelab;

using Change = std::function<void(Setup&)>;
Q_DECLARE_METATYPE(Change)

namespace {

// A legal setup: a 9-ft table, the cue ball and the 1 ball, a shot on the cue ball.
Setup base()
{
    Setup s;
    Ball cue;
    cue.id = "cue";
    cue.state.position = Vec2(0.6, 0.6);
    Ball one;
    one.id = "1";
    one.state.position = Vec2(1.8, 0.6);
    s.balls = {cue, one};
    s.shot = CueStrike{};
    s.shot->ball = "cue";
    return s;
}

}  // namespace

class TestRealPlay : public QObject {
    Q_OBJECT

private slots:
    void warned_data();
    void warned();
    void notWarned_data();
    void notWarned();
    void everyWarningInOrder();
};

void TestRealPlay::warned_data()
{
    QTest::addColumn<Change>("change");
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("ball");     // the id the warning names, "" when none
    QTest::addColumn<QString>("message");  // the whole message, worked by hand from RealPlay's limits

    QTest::newRow("40 m table") << Change([](Setup& s) { s.table.length = 40.0; }) << "table.length" << ""
                                << "40 m is beyond real play (up to 10 m); it loads and simulates as given";
    QTest::newRow("12 m wide table") << Change([](Setup& s) { s.table.width = 12.0; }) << "table.width" << ""
                                     << "12 m is beyond real play (up to 10 m); it loads and simulates as given";
    QTest::newRow("40 m/s ball") << Change([](Setup& s) { s.balls[1].state.velocity = Vec2(24.0, -32.0); })
                                 << "balls[1].velocity" << "1"
                                 << "ball \"1\": velocity 40 m/s is beyond real play (up to 20 m/s); it loads and simulates as given";
    QTest::newRow("3000 rad/s spin") << Change([](Setup& s) { s.balls[0].state.spin = Vec3(0.0, 1800.0, 2400.0); })
                                     << "balls[0].spin" << "cue"
                                     << "ball \"cue\": spin 3000 rad/s is beyond real play (up to 2000 rad/s); it loads and simulates as given";
    QTest::newRow("40 m/s shot") << Change([](Setup& s) { s.shot->speed = 40.0; }) << "shot.speed" << ""
                                 << "40 m/s is beyond real play (up to 20 m/s); it loads and simulates as given";
    QTest::newRow("heading -7200") << Change([](Setup& s) { s.shot->headingDeg = -7200.0; }) << "shot.heading" << ""
                                   << "7200° is beyond real play (up to 3600°); it loads and simulates as given";
    QTest::newRow("cue of 10 kg") << Change([](Setup& s) { s.shot->cueMass = 10.0; }) << "shot.cue_mass" << ""
                                  << "10 kg is beyond real play (up to 5 kg); it loads and simulates as given";
    QTest::newRow("gravity 200") << Change([](Setup& s) { s.physics.gravity = 200.0; }) << "physics.gravity" << ""
                                 << "200 m/s² is beyond real play (up to 100 m/s²); it loads and simulates as given";
    QTest::newRow("mu_roll 20") << Change([](Setup& s) { s.physics.muRoll = 20.0; }) << "physics.mu_roll" << ""
                                << "20 is beyond real play (up to 10); it loads and simulates as given";
    QTest::newRow("cushion friction 11") << Change([](Setup& s) { s.physics.cushionFriction = 11.0; })
                                         << "physics.ball_cushion.friction" << ""
                                         << "11 is beyond real play (up to 10); it loads and simulates as given";
    QTest::newRow("ball of 8 kg") << Change([](Setup& s) { s.balls[1].mass = 8.0; }) << "balls[1].mass" << "1"
                                  << "ball \"1\": mass 8 kg is beyond real play (up to 5 kg); it loads and simulates as given";
    QTest::newRow("max_time of two days") << Change([](Setup& s) { s.simulation.maxTime = 172800.0; })
                                          << "simulation.max_time" << ""
                                          << "172800 s is beyond real play (up to 86400 s); it loads and simulates as given";
    QTest::newRow("frame_dt 20 s") << Change([](Setup& s) { s.simulation.frameDt = 20.0; }) << "simulation.frame_dt" << ""
                                   << "20 s is beyond real play (up to 10 s); it loads and simulates as given";
}

void TestRealPlay::warned()
{
    QFETCH(Change, change);
    QFETCH(QString, path);
    QFETCH(QString, ball);
    QFETCH(QString, message);
    Setup s = base();
    change(s);
    const std::vector<SetupProblem> problems = validateSetup(s);
    QVERIFY2(problems.empty(), problems.empty() ? "" : problems.front().message.c_str());
    const std::vector<SetupWarning> warnings = setupWarnings(s);
    QCOMPARE(warnings.size(), std::size_t(1));
    QCOMPARE(QString::fromStdString(warnings[0].path), path);
    QCOMPARE(QString::fromStdString(warnings[0].ballId), ball);
    QCOMPARE(QString::fromStdString(warnings[0].message), message);
}

void TestRealPlay::notWarned_data()
{
    QTest::addColumn<Change>("change");
    QTest::newRow("the base setup") << Change([](Setup&) {});
    QTest::newRow("every real-play limit itself") << Change([](Setup& s) {
        s.shot->speed = RealPlay::speed;
        s.shot->headingDeg = -RealPlay::heading;
        s.shot->cueMass = RealPlay::cueMass;
        s.balls[0].state.velocity = RealPlay::speed * Vec2(0.6, 0.8);
        s.balls[0].state.spin = RealPlay::spin * Vec3(0.0, 0.6, 0.8);
        s.balls[1].mass = RealPlay::mass;
        s.physics.gravity = RealPlay::gravity;
        s.physics.muSlide = s.physics.muRoll = s.physics.muSpin = RealPlay::friction;
        s.physics.ballBallFriction = s.physics.cushionFriction = RealPlay::friction;
        s.simulation.frameDt = RealPlay::frameDt;
        s.simulation.maxTime = RealPlay::maxTime;
    });
    // Refused values are the validator's: they get a refusal, not a warning too.
    QTest::newRow("a refused 1e300 m/s shot") << Change([](Setup& s) { s.shot->speed = 1e300; });
    QTest::newRow("a refused infinite spin") << Change([](Setup& s) { s.balls[0].state.spin.z() = qInf(); });
    // The fixed friction is not read with Alciatore's fit.
    QTest::newRow("alciatore ignores the fixed friction") << Change([](Setup& s) {
        s.physics.ballBallFrictionKind = BallBallFriction::Alciatore;
        s.physics.ballBallFriction = 50.0;
    });
}

void TestRealPlay::notWarned()
{
    QFETCH(Change, change);
    Setup s = base();
    change(s);
    const std::vector<SetupWarning> warnings = setupWarnings(s);
    QVERIFY2(warnings.empty(), warnings.empty() ? "" : warnings.front().message.c_str());
}

// Several values beyond real play: one warning each, in the order of the file (table, physics, balls,
// shot, simulation).
void TestRealPlay::everyWarningInOrder()
{
    Setup s = base();
    s.simulation.maxTime = 100000.0;
    s.shot->speed = 30.0;
    s.balls[0].state.velocity = Vec2(30.0, 0.0);
    s.physics.gravity = 101.0;
    s.table.length = 40.0;
    s.table.kind = TableKind::Carom;
    const std::vector<SetupWarning> warnings = setupWarnings(s);
    QStringList paths;
    for (const SetupWarning& w : warnings) paths << QString::fromStdString(w.path);
    QCOMPARE(paths, QStringList({"table.length", "physics.gravity", "balls[0].velocity", "shot.speed", "simulation.max_time"}));
}

QTEST_GUILESS_MAIN(TestRealPlay)
#include "tst_realplay.moc"
