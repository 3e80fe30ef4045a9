// The one validator of a legal setup (core/setup/LegalSetup.h): one named row per rule, each with
// the JSON path and the ball's id it must name; every problem of a setup reported in order; a ball's
// own problems alone; the tolerance of 1e-9 m.

#include "LegalSetup.h"

#include <QtTest>

#include <cmath>
#include <functional>
#include <limits>

using namespace cuelab;

using Breakage = std::function<void(Setup&)>;
Q_DECLARE_METATYPE(Breakage)

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

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

Ball& ball(Setup& s, std::size_t i) { return s.balls[i]; }

}  // namespace

class TestLegalSetup : public QObject {
    Q_OBJECT
private slots:
    void baseIsLegal();
    void rule_data();
    void rule();
    void everyProblemInOrder();
    void brokenTableSkipsTheGeometry();
    void alciatoreFrictionNeedsNoNumber();
    void overlapWithinTolerance();
    void unequalRadiiTouchCloser();
    void aBallInTheAirIsApartInSpace();
    void oneBallsProblems();
    void lengthsAndNumbersForMessages();
    void boundsThemselvesAreLegal();
};

void TestLegalSetup::baseIsLegal()
{
    QVERIFY(validateSetup(base()).empty());
    QVERIFY(!firstSetupProblem(base()));
    Setup empty = base();
    empty.balls.clear();
    empty.shot.reset();
    QVERIFY(validateSetup(empty).empty());
}

void TestLegalSetup::rule_data()
{
    QTest::addColumn<Breakage>("breakage");
    QTest::addColumn<QString>("path");      // the JSON path the problem must name
    QTest::addColumn<QString>("ballId");    // the ball it must name ("" = none)
    QTest::addColumn<QString>("fragment");  // a piece of its message

    // table
    QTest::newRow("table length zero") << Breakage([](Setup& s) { s.table.length = 0.0; }) << "table.length" << ""
                                       << "must be greater than 0";
    QTest::newRow("table width not finite") << Breakage([](Setup& s) { s.table.width = kNaN; }) << "table.width" << ""
                                            << "must be a finite number";
    QTest::newRow("cushion height negative") << Breakage([](Setup& s) { s.table.cushionHeight = -0.01; })
                                             << "table.cushion_height" << "" << "greater than 0 (found -0.01)";
    QTest::newRow("table too short for its pockets") << Breakage([](Setup& s) { s.table.length = 0.3; s.balls.clear(); s.shot.reset(); })
                                                     << "table.length" << "" << "too short for its pockets";
    QTest::newRow("table too narrow for its pockets") << Breakage([](Setup& s) { s.table.width = 0.1; s.balls.clear(); s.shot.reset(); })
                                                      << "table.width" << "" << "too narrow for its pockets";
    // physics
    QTest::newRow("gravity zero") << Breakage([](Setup& s) { s.physics.gravity = 0.0; }) << "physics.gravity" << ""
                                  << "greater than 0";
    QTest::newRow("gravity infinite") << Breakage([](Setup& s) { s.physics.gravity = kInf; }) << "physics.gravity" << ""
                                      << "finite number (found inf)";
    QTest::newRow("mu_slide zero") << Breakage([](Setup& s) { s.physics.muSlide = 0.0; }) << "physics.mu_slide" << ""
                                   << "greater than 0";
    QTest::newRow("mu_roll negative") << Breakage([](Setup& s) { s.physics.muRoll = -0.01; }) << "physics.mu_roll" << ""
                                      << "greater than 0";
    QTest::newRow("mu_spin not finite") << Breakage([](Setup& s) { s.physics.muSpin = kNaN; }) << "physics.mu_spin" << ""
                                        << "finite";
    QTest::newRow("ball-ball restitution above 1") << Breakage([](Setup& s) { s.physics.ballBallRestitution = 1.5; })
                                                   << "physics.ball_ball.restitution" << "" << "between 0 and 1 (found 1.5)";
    QTest::newRow("ball-ball friction negative") << Breakage([](Setup& s) { s.physics.ballBallFriction = -0.01; })
                                                 << "physics.ball_ball.friction" << "" << "must not be negative";
    QTest::newRow("ball-cushion restitution below 0") << Breakage([](Setup& s) { s.physics.cushionRestitution = -0.1; })
                                                      << "physics.ball_cushion.restitution" << "" << "between 0 and 1";
    QTest::newRow("ball-cushion friction negative") << Breakage([](Setup& s) { s.physics.cushionFriction = -1.0; })
                                                    << "physics.ball_cushion.friction" << "" << "must not be negative";
    // balls: values
    QTest::newRow("id empty") << Breakage([](Setup& s) { ball(s, 1).id.clear(); }) << "balls[1].id" << ""
                              << "the id must not be empty";
    QTest::newRow("id duplicate") << Breakage([](Setup& s) { ball(s, 1).id = "cue"; }) << "balls[1].id" << "cue"
                                  << "duplicate id \"cue\" (balls[0] has it too)";
    QTest::newRow("position not finite") << Breakage([](Setup& s) { ball(s, 1).state.position.y() = kNaN; })
                                         << "balls[1].position[1]" << "1" << "ball \"1\": position[1] must be a finite number";
    QTest::newRow("velocity infinite") << Breakage([](Setup& s) { ball(s, 0).state.velocity.x() = -kInf; })
                                       << "balls[0].velocity[0]" << "cue" << "velocity[0] must be a finite number (found -inf)";
    QTest::newRow("spin not finite") << Breakage([](Setup& s) { ball(s, 0).state.spin.z() = kNaN; })
                                     << "balls[0].spin[2]" << "cue" << "finite";
    QTest::newRow("radius zero") << Breakage([](Setup& s) { ball(s, 1).radius = 0.0; }) << "balls[1].radius" << "1"
                                 << "ball \"1\": radius must be greater than 0 (found 0)";
    QTest::newRow("radius not finite") << Breakage([](Setup& s) { ball(s, 1).radius = kInf; }) << "balls[1].radius" << "1"
                                       << "finite";
    QTest::newRow("mass negative") << Breakage([](Setup& s) { ball(s, 0).mass = -0.17; }) << "balls[0].mass" << "cue"
                                   << "ball \"cue\": mass must be greater than 0";
    // shot
    QTest::newRow("shot names no ball") << Breakage([](Setup& s) { s.shot->ball = "9"; }) << "shot.ball" << ""
                                        << "there is no ball \"9\"";
    QTest::newRow("shot speed negative") << Breakage([](Setup& s) { s.shot->speed = -2.0; }) << "shot.speed" << ""
                                         << "must not be negative";
    QTest::newRow("shot heading not finite") << Breakage([](Setup& s) { s.shot->headingDeg = kNaN; }) << "shot.heading" << ""
                                             << "finite";
    QTest::newRow("shot elevation above 90") << Breakage([](Setup& s) { s.shot->elevationDeg = 95.0; }) << "shot.elevation"
                                             << "" << "between 0 and 90 degrees (found 95)";
    QTest::newRow("shot elevation negative") << Breakage([](Setup& s) { s.shot->elevationDeg = -5.0; }) << "shot.elevation"
                                             << "" << "between 0 and 90";
    QTest::newRow("tip misses, side") << Breakage([](Setup& s) { s.shot->side = 0.9; s.shot->height = 0.5; }) << "shot.side"
                                      << "" << "the tip misses the ball";
    QTest::newRow("tip misses, height") << Breakage([](Setup& s) { s.shot->height = -1.0; }) << "shot.height" << ""
                                        << "the tip misses the ball";
    QTest::newRow("cue mass zero") << Breakage([](Setup& s) { s.shot->cueMass = 0.0; }) << "shot.cue_mass" << ""
                                   << "greater than 0";
    // simulation
    QTest::newRow("frame_dt zero") << Breakage([](Setup& s) { s.simulation.frameDt = 0.0; }) << "simulation.frame_dt" << ""
                                   << "greater than 0";
    QTest::newRow("max_time negative") << Breakage([](Setup& s) { s.simulation.maxTime = -1.0; }) << "simulation.max_time"
                                       << "" << "greater than 0";
    // safe bounds (SetupBounds): finite but absurd values are refused too; values beyond real play
    // but within these bounds load (tst_realplay)
    QTest::newRow("shot speed 1e300") << Breakage([](Setup& s) { s.shot->speed = 1e300; }) << "shot.speed" << ""
                                      << "must be at most 1000 m/s (found 1e+300 m/s)";
    QTest::newRow("shot speed just above 1000 m/s") << Breakage([](Setup& s) { s.shot->speed = 1000.5; }) << "shot.speed" << ""
                                                    << "at most 1000 m/s (found 1000.5 m/s)";
    QTest::newRow("ball velocity 1e300") << Breakage([](Setup& s) { ball(s, 0).state.velocity = Vec2(1e300, 0.0); })
                                         << "balls[0].velocity" << "cue" << "ball \"cue\": velocity must be at most 1000 m/s";
    QTest::newRow("ball speed 1060 m/s diagonally") << Breakage([](Setup& s) { ball(s, 1).state.velocity = Vec2(750.0, -750.0); })
                                                    << "balls[1].velocity" << "1" << "at most 1000 m/s (found 1060.66 m/s)";
    QTest::newRow("ball spin 1e300") << Breakage([](Setup& s) { ball(s, 1).state.spin = Vec3(0.0, 0.0, -1e300); })
                                     << "balls[1].spin" << "1" << "ball \"1\": spin must be at most 100000 rad/s";
    QTest::newRow("ball position 1e300") << Breakage([](Setup& s) { ball(s, 1).state.position = Vec2(1e300, 0.6); })
                                         << "balls[1].position" << "1" << "outside the playing surface";
    QTest::newRow("ball radius 1 km") << Breakage([](Setup& s) { ball(s, 1).radius = 1000.0; }) << "balls[1].radius" << "1"
                                      << "radius must be at most 500 m (found 1000 m)";
    QTest::newRow("ball mass 1e300") << Breakage([](Setup& s) { ball(s, 0).mass = 1e300; }) << "balls[0].mass" << "cue"
                                     << "mass must be at most 1e+06 kg";
    QTest::newRow("table length 1e300") << Breakage([](Setup& s) { s.table.length = 1e300; }) << "table.length" << ""
                                        << "must be at most 1000 m (found 1e+300 m)";
    QTest::newRow("table width 1001 m") << Breakage([](Setup& s) { s.table.width = 1001.0; }) << "table.width" << ""
                                        << "at most 1000 m";
    QTest::newRow("cushion height 2 km") << Breakage([](Setup& s) { s.table.cushionHeight = 2000.0; }) << "table.cushion_height"
                                         << "" << "at most 1000 m";
    QTest::newRow("gravity 1e300") << Breakage([](Setup& s) { s.physics.gravity = 1e300; }) << "physics.gravity" << ""
                                   << "at most 10000 m/s²";
    QTest::newRow("mu_slide 1e300") << Breakage([](Setup& s) { s.physics.muSlide = 1e300; }) << "physics.mu_slide" << ""
                                    << "at most 1000 (found 1e+300)";
    QTest::newRow("mu_roll 1001") << Breakage([](Setup& s) { s.physics.muRoll = 1001.0; }) << "physics.mu_roll" << "" << "at most 1000";
    QTest::newRow("mu_spin 1e300") << Breakage([](Setup& s) { s.physics.muSpin = 1e300; }) << "physics.mu_spin" << "" << "at most 1000";
    QTest::newRow("ball-ball friction 1e300") << Breakage([](Setup& s) { s.physics.ballBallFriction = 1e300; })
                                              << "physics.ball_ball.friction" << "" << "at most 1000";
    QTest::newRow("ball-cushion friction 1e300") << Breakage([](Setup& s) { s.physics.cushionFriction = 1e300; })
                                                 << "physics.ball_cushion.friction" << "" << "at most 1000";
    QTest::newRow("shot heading 1e300") << Breakage([](Setup& s) { s.shot->headingDeg = 1e300; }) << "shot.heading" << ""
                                        << "must lie between -1e+06 and 1e+06 degrees (found 1e+300)";
    QTest::newRow("shot heading -1000001") << Breakage([](Setup& s) { s.shot->headingDeg = -1000001.0; }) << "shot.heading" << ""
                                           << "between -1e+06 and 1e+06";
    QTest::newRow("cue mass 1e300") << Breakage([](Setup& s) { s.shot->cueMass = 1e300; }) << "shot.cue_mass" << ""
                                    << "at most 1e+06 kg";
    QTest::newRow("end mass above the cue's") << Breakage([](Setup& s) { s.shot->endMass = 1.0; }) << "shot.end_mass" << ""
                                              << "must not exceed the cue's mass of 0.567 kg (found 1 kg)";
    QTest::newRow("frame_dt 1e300") << Breakage([](Setup& s) { s.simulation.frameDt = 1e300; }) << "simulation.frame_dt" << ""
                                    << "at most 1e+06 s";
    QTest::newRow("max_time 1e300") << Breakage([](Setup& s) { s.simulation.maxTime = 1e300; }) << "simulation.max_time" << ""
                                    << "at most 1e+06 s";
    // geometry
    QTest::newRow("cushion above the balls") << Breakage([](Setup& s) { s.table.cushionHeight = 0.06; s.balls.pop_back(); }) << "balls[0].radius"
                                             << "cue" << "ball \"cue\" (radius 0.028575 m) is lower than the cushion nose";
    QTest::newRow("outside the playing surface") << Breakage([](Setup& s) { ball(s, 1).state.position = Vec2(2.6, 0.6); })
                                                 << "balls[1].position" << "1"
                                                 << "ball \"1\" is outside the playing surface (0 to 2.54 m by 0 to 1.27 m)";
    QTest::newRow("in a corner pocket") << Breakage([](Setup& s) { ball(s, 0).state.position = Vec2(0.01, 0.01); })
                                        << "balls[0].position" << "cue" << "ball \"cue\" lies in pocket \"pocket-bl\"";
    QTest::newRow("into a rail") << Breakage([](Setup& s) { ball(s, 0).state.position = Vec2(0.6, 0.02); })
                                 << "balls[0].position" << "cue" << "ball \"cue\" overlaps cushion \"rail-b-left\" by 8.6 mm";
    QTest::newRow("into a closed rail") << Breakage([](Setup& s) {
        s.table.kind = TableKind::Carom;
        ball(s, 0).state.position = Vec2(0.02, 0.7);
    }) << "balls[0].position" << "cue" << "overlaps cushion \"rail-left\"";
    QTest::newRow("into a jaw tip") << Breakage([](Setup& s) {
        const Table table = makeTable(TableKind::Pool9ft);
        for (const JawTip& j : table.jaws)
            if (j.id == "jaw-b-left") ball(s, 0).state.position = j.centre + (j.radius + table.ballRadius - 0.001) * Vec2(0.6, 0.8);
    }) << "balls[0].position" << "cue" << "overlaps jaw \"jaw-b-left\" by 1.0 mm";
    QTest::newRow("overlapping balls") << Breakage([](Setup& s) { ball(s, 1).state.position = Vec2(0.6550499, 0.6); })
                                       << "balls[1].position" << "1" << "ball \"1\" overlaps ball \"cue\" by 2.1 mm";
    QTest::newRow("overlap just beyond tolerance") << Breakage([](Setup& s) { ball(s, 1).state.position = Vec2(0.657149998, 0.6); })
                                                   << "balls[1].position" << "1" << "overlaps ball \"cue\" by 2.0 nm";
}

void TestLegalSetup::rule()
{
    QFETCH(Breakage, breakage);
    QFETCH(QString, path);
    QFETCH(QString, ballId);
    QFETCH(QString, fragment);
    Setup s = base();
    breakage(s);
    const std::vector<SetupProblem> problems = validateSetup(s);
    QCOMPARE(problems.size(), std::size_t{1});
    const SetupProblem& p = problems.front();
    QCOMPARE(QString::fromStdString(p.path), path);
    QCOMPARE(QString::fromStdString(p.ballId), ballId);
    if (!ballId.isEmpty()) {
        QCOMPARE(QString::fromStdString(s.balls[static_cast<std::size_t>(p.ballIndex)].id), ballId);
        QVERIFY2(QString::fromStdString(p.message).contains(QStringLiteral("\"%1\"").arg(ballId)), p.message.c_str());
    }
    QVERIFY2(QString::fromStdString(p.message).contains(fragment), p.message.c_str());
    const std::optional<SetupProblem> first = firstSetupProblem(s);
    QVERIFY(first);
    QCOMPARE(first->message, p.message);
}

void TestLegalSetup::everyProblemInOrder()
{
    Setup s = base();
    s.physics.muRoll = 0.0;                         // physics
    ball(s, 1).mass = 0.0;                          // a ball's value
    s.shot->elevationDeg = 91.0;                    // the shot
    ball(s, 0).state.position = Vec2(-0.1, 0.6);    // the geometry
    Ball extra = ball(s, 1);
    extra.id = "2";
    extra.mass = 0.17;
    extra.state.position = Vec2(1.81, 0.6);         // overlaps "1"
    s.balls.push_back(extra);
    const std::vector<SetupProblem> problems = validateSetup(s);
    QStringList paths;
    for (const SetupProblem& p : problems) paths << QString::fromStdString(p.path);
    QCOMPARE(paths, QStringList({"physics.mu_roll", "balls[1].mass", "shot.elevation", "balls[0].position",
                                 "balls[2].position"}));
    QCOMPARE(problems.back().ballId, std::string("2"));
    QCOMPARE(problems.back().ballIndex, 2);
    QCOMPARE(firstSetupProblem(s)->path, std::string("physics.mu_roll"));
}

void TestLegalSetup::brokenTableSkipsTheGeometry()
{
    // No table to check against: only the table's own problem, not one per ball.
    Setup s = base();
    s.table.length = -2.0;
    const std::vector<SetupProblem> problems = validateSetup(s);
    QCOMPARE(problems.size(), std::size_t{1});
    QCOMPARE(problems.front().path, std::string("table.length"));
    // Nor the place of a ball whose position is not a number.
    s = base();
    ball(s, 1).state.position = Vec2(kNaN, kNaN);
    QCOMPARE(validateSetup(s).size(), std::size_t{2});  // position[0] and position[1], nothing more
}

void TestLegalSetup::alciatoreFrictionNeedsNoNumber()
{
    Setup s = base();
    s.physics.ballBallFrictionKind = BallBallFriction::Alciatore;
    s.physics.ballBallFriction = -1.0;  // unused with the fit
    QVERIFY(validateSetup(s).empty());
}

void TestLegalSetup::overlapWithinTolerance()
{
    Setup s = base();
    ball(s, 1).state.position = Vec2(0.6 + 2 * 0.028575 - 0.9e-9, 0.6);
    QVERIFY(validateSetup(s).empty());
    ball(s, 1).state.position = Vec2(0.6 + 2 * 0.028575 - 1.1e-9, 0.6);
    QCOMPARE(validateSetup(s).size(), std::size_t{1});
}

void TestLegalSetup::unequalRadiiTouchCloser()
{
    // A 2 3/8 in bar-box cue ball frozen to a 2 1/4 in ball: their centres sit at different heights,
    // so they touch at the horizontal distance 2 sqrt(R1 R2) (21.5 um less than R1 + R2), which is legal.
    Setup s = base();
    const double R1 = 0.028575, R2 = 0.0301625, d = 2.0 * std::sqrt(R1 * R2);
    ball(s, 0).radius = R2;
    ball(s, 1).state.position = Vec2(0.6 + d - 0.9e-9, 0.6);
    QVERIFY(validateSetup(s).empty());
    QVERIFY(validateBall(s, 1).empty());
    ball(s, 1).state.position = Vec2(0.6 + d - 1.1e-9, 0.6);
    QCOMPARE(validateSetup(s).size(), std::size_t{1});
    QCOMPARE(validateBall(s, 1).size(), std::size_t{1});
    ball(s, 1).state.position = Vec2(0.6 + R1 + R2 - 10e-6, 0.6);  // inside R1 + R2, outside d
    QVERIFY(validateSetup(s).empty());
}

void TestLegalSetup::aBallInTheAirIsApartInSpace()
{
    // A ball given a height is apart from another by the distance of their centres in space: set
    // on the other's shoulder at 30 degrees it touches (legal), a nanometre and more lower it
    // overlaps; straight above by more than a diameter it is legal over the other's position.
    Setup s = base();
    const double R = 0.028575, theta = 30.0 * M_PI / 180.0;
    const Vec2 low = ball(s, 0).state.position;
    ball(s, 1).state.position = low + Vec2(2.0 * R * std::sin(theta), 0.0);
    ball(s, 1).state.z = 2.0 * R * std::cos(theta);
    QVERIFY(validateSetup(s).empty());
    ball(s, 1).state.z = 2.0 * R * std::cos(theta) - 2e-9 / std::cos(theta);
    QCOMPARE(validateBall(s, 1).size(), std::size_t{1});
    QVERIFY(validateBall(s, 1).front().message.find("overlaps ball") != std::string::npos);
    ball(s, 1).state.position = low;
    ball(s, 1).state.z = 2.0 * R + 1e-6;
    QVERIFY(validateSetup(s).empty());
}

void TestLegalSetup::oneBallsProblems()
{
    Setup s = base();
    s.physics.muRoll = 0.0;  // not the ball's problem
    Ball two = ball(s, 1);
    two.id = "2";
    two.state.position = Vec2(1.2, 0.6);
    s.balls.push_back(two);
    ball(s, 1).state.position = Vec2(1.21, 0.6);  // "1" overlaps "2"
    ball(s, 1).id = "2";                           // and takes its id
    const std::vector<SetupProblem> problems = validateBall(s, 1);
    QCOMPARE(problems.size(), std::size_t{2});
    QCOMPARE(problems[0].path, std::string("balls[1].id"));       // the later "2" is named too
    QCOMPARE(problems[1].path, std::string("balls[1].position"));
    QVERIFY(validateBall(s, 0).empty());
    QVERIFY(validateBall(s, 7).empty());
}

void TestLegalSetup::lengthsAndNumbersForMessages()
{
    QCOMPARE(describeLength(0.0021), std::string("2.1 mm"));
    QCOMPARE(describeLength(3.5e-5), std::string("35.0 µm"));
    QCOMPARE(describeLength(2e-9), std::string("2.0 nm"));
    QCOMPARE(describeLength(0.25), std::string("0.250 m"));
    QCOMPARE(describeNumber(-0.03), std::string("-0.03"));
    QCOMPARE(describeNumber(1e-5), std::string("1e-05"));
    QCOMPARE(describeNumber(2.54), std::string("2.54"));
}

// Every bound of SetupBounds is itself a legal value: the limits are inclusive.
void TestLegalSetup::boundsThemselvesAreLegal()
{
    Setup s = base();
    s.shot->speed = SetupBounds::speed;
    s.shot->headingDeg = -SetupBounds::heading;
    s.shot->cueMass = SetupBounds::cueMass;
    s.shot->endMass = SetupBounds::cueMass;
    ball(s, 0).state.velocity = SetupBounds::speed * Vec2(0.6, 0.8);
    ball(s, 0).state.spin = SetupBounds::spin * Vec3(0.0, 0.6, 0.8);
    ball(s, 1).mass = SetupBounds::mass;
    s.physics.gravity = SetupBounds::gravity;
    s.physics.muSlide = s.physics.muRoll = s.physics.muSpin = SetupBounds::friction;
    s.physics.ballBallFriction = s.physics.cushionFriction = SetupBounds::friction;
    s.simulation.frameDt = SetupBounds::frameDt;
    s.simulation.maxTime = SetupBounds::maxTime;
    const std::vector<SetupProblem> problems = validateSetup(s);
    QVERIFY2(problems.empty(), problems.empty() ? "" : problems.front().message.c_str());
    // A large closed table with a large ball: the geometric bounds together.
    Setup big;
    big.table.kind = TableKind::Carom;
    big.table.length = big.table.width = SetupBounds::tableSize;
    big.table.cushionHeight = 0.6;  // below the ball's 2R
    Ball b;
    b.id = "big";
    b.radius = SetupBounds::radius;
    b.mass = SetupBounds::mass;
    b.state.position = Vec2(500.0, 500.0);
    big.balls.push_back(b);
    const std::vector<SetupProblem> bigProblems = validateSetup(big);
    QVERIFY2(bigProblems.empty(), bigProblems.empty() ? "" : bigProblems.front().message.c_str());
}

QTEST_GUILESS_MAIN(TestLegalSetup)
#include "tst_legalsetup.moc"
