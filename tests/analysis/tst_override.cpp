// Overrides by key (--set): every key of CONTRACT.md sets its value, unknown keys and values of the
// wrong type are named, table.kind moves only the balls that followed the old default, and an
// override that makes the setup illegal is refused by the validator with the loader's kind of message.

#include "AnalysisTestSetups.h"
#include "LegalSetup.h"
#include "Override.h"
#include "Refusal.h"

#include "resolve/CushionModel.h"

#include <QFile>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace cuelab;
using namespace cuelab::analysis;

class TestOverride : public QObject {
    Q_OBJECT

private slots:
    void numericKeys_data();
    void numericKeys();
    void textKeys();
    void unknownKeys_data();
    void unknownKeys();
    void badValues_data();
    void badValues();
    void tableKindMovesDefaultBallsOnly();
    void illegalOverrideIsRefused_data();
    void illegalOverrideIsRefused();
    void assignmentAndNumbers();
    void everyListedKeyResolves();
    void everyRegisteredModel();
    void modelParametersFromTheRegistry();
    void unknownKeyListsTheValidOnes();
    void docsListEveryModelAndParameter();
};

void TestOverride::numericKeys_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("value");
    for (const char* key :
         {"shot.speed", "shot.heading", "shot.elevation", "shot.side", "shot.height", "shot.cue_mass", "shot.end_mass",
          "physics.gravity", "physics.mu_slide", "physics.mu_roll", "physics.mu_spin", "physics.ball_ball.restitution",
          "physics.ball_ball.friction", "physics.ball_cushion.restitution", "physics.ball_cushion.friction",
          "table.length", "table.width", "table.cushion_height", "balls.cue.x", "balls.cue.y", "balls.1.vx",
          "balls.1.vy", "balls.1.wx", "balls.1.wy", "balls.1.wz", "balls.cue.radius", "balls.cue.mass",
          "simulation.max_time", "simulation.frame_dt"})
        QTest::newRow(key) << QString::fromLatin1(key) << 0.3125;
}

void TestOverride::numericKeys()
{
    QFETCH(QString, key);
    QFETCH(double, value);
    Setup setup = test::example("half-ball-cut.json");
    QVERIFY(!applyOverride(setup, key.toStdString(), "0.3125"));
    auto p = Parameter::resolve(setup, key.toStdString());
    QVERIFY(std::holds_alternative<Parameter>(p));
    QCOMPARE(std::get<Parameter>(p).number(setup), value);
    QCOMPARE(std::get<Parameter>(p).text(setup), std::string("0.3125"));
}

void TestOverride::textKeys()
{
    Setup setup = test::example("half-ball-cut.json");
    QVERIFY(!applyOverride(setup, "physics.ball_ball.model", "frictional"));
    QVERIFY(setup.physics.ballBallModel == BallBallModel::Frictional);
    QVERIFY(!applyOverride(setup, "physics.ball_ball.friction", "alciatore"));
    QVERIFY(setup.physics.ballBallFrictionKind == BallBallFriction::Alciatore);
    QVERIFY(!applyOverride(setup, "physics.ball_ball.friction", "0.07"));
    QVERIFY(setup.physics.ballBallFrictionKind == BallBallFriction::Fixed);
    QCOMPARE(setup.physics.ballBallFriction, 0.07);
    QVERIFY(!applyOverride(setup, "physics.ball_cushion.model", "mirror"));
    QVERIFY(setup.physics.ballCushionModel == BallCushionModel::Mirror);
    QVERIFY(!applyOverride(setup, "table.pockets", "false"));
    QCOMPARE(setup.table.pockets, false);
    QVERIFY(!applyOverride(setup, "table.kind", "pool-8ft"));
    QVERIFY(setup.table.kind == TableKind::Pool8ft);
    QVERIFY(!applyOverride(setup, "shot.ball", "1"));
    QCOMPARE(setup.shot->ball, std::string("1"));
    // A velocity given to a resting ball makes it slide: the label follows the numbers.
    QVERIFY(!applyOverride(setup, "balls.1.vx", "0.5"));
    QVERIFY(setup.balls[1].state.motion == MotionState::Sliding);
}

void TestOverride::unknownKeys_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("named");
    QTest::newRow("typo") << "shot.sped" << "\"shot.sped\"";
    QTest::newRow("no section") << "speed" << "\"speed\"";
    QTest::newRow("unknown ball") << "balls.9.x" << "no ball \"9\"";
    QTest::newRow("unknown ball field") << "balls.cue.z" << "\"balls.cue.z\"";
    QTest::newRow("no field") << "balls.cue" << "\"balls.cue\"";
    QTest::newRow("physics typo") << "physics.ball_ball.restitutoin" << "\"physics.ball_ball.restitutoin\"";
    QTest::newRow("empty") << "" << "\"\"";
}

void TestOverride::unknownKeys()
{
    QFETCH(QString, key);
    QFETCH(QString, named);
    Setup setup = test::example("half-ball-cut.json");
    const Setup before = setup;
    const auto error = applyOverride(setup, key.toStdString(), "1");
    QVERIFY(error);
    QVERIFY(error->kind == OverrideError::Kind::UnknownKey);
    QVERIFY2(QString::fromStdString(error->message).contains(named), error->message.c_str());
    QCOMPARE(setup.shot->speed, before.shot->speed);
}

void TestOverride::badValues_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("value");
    QTest::newRow("text for a number") << "shot.speed" << "fast";
    QTest::newRow("trailing junk") << "shot.speed" << "3m/s";
    QTest::newRow("empty number") << "shot.heading" << "";
    QTest::newRow("infinite") << "shot.speed" << "inf";
    QTest::newRow("nan") << "balls.cue.x" << "nan";
    QTest::newRow("bool") << "table.pockets" << "yes";
    QTest::newRow("table kind") << "table.kind" << "pool-10ft";
    QTest::newRow("ball-ball model") << "physics.ball_ball.model" << "sticky";
    QTest::newRow("cushion model") << "physics.ball_cushion.model" << "rubber";
    QTest::newRow("friction text") << "physics.ball_ball.friction" << "high";
    QTest::newRow("shot ball") << "shot.ball" << "7";
}

void TestOverride::badValues()
{
    QFETCH(QString, key);
    QFETCH(QString, value);
    Setup setup = test::example("half-ball-cut.json");
    const auto error = applyOverride(setup, key.toStdString(), value.toStdString());
    QVERIFY(error);
    QVERIFY(error->kind == OverrideError::Kind::BadValue);
    const QString message = QString::fromStdString(error->message);
    QVERIFY2(message.contains(key) && message.contains(QLatin1Char('"') + value + QLatin1Char('"')), qPrintable(message));
}

void TestOverride::tableKindMovesDefaultBallsOnly()
{
    Setup setup = test::example("half-ball-cut.json");
    setup.balls[1].radius = 0.03;  // given on purpose: kept
    QVERIFY(!applyOverride(setup, "table.kind", "snooker"));
    const Table snooker = makeTable(TableKind::Snooker);
    QCOMPARE(setup.balls[0].radius, snooker.ballRadius);
    QCOMPARE(setup.balls[0].mass, snooker.ballMass);
    QCOMPARE(setup.balls[1].radius, 0.03);
    QCOMPARE(setup.balls[1].mass, snooker.ballMass);
    // Written and read again, the file holds the same balls (the writer's rule is the same).
    QString error;
    const auto again = io::parseSetup(io::serializeSetup(setup), QStringLiteral("x.json"), &error);
    QVERIFY2(again, qPrintable(error));
    QCOMPARE(again->balls[0].radius, setup.balls[0].radius);
    QCOMPARE(again->balls[1].radius, setup.balls[1].radius);
}

void TestOverride::illegalOverrideIsRefused_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("path");
    QTest::newRow("restitution") << "physics.ball_ball.restitution" << "1.5" << "physics.ball_ball.restitution";
    QTest::newRow("negative speed") << "shot.speed" << "-1" << "shot.speed";
    QTest::newRow("tip off the ball") << "shot.side" << "1.2" << "shot.side";
    QTest::newRow("off the cloth") << "balls.1.x" << "3" << "balls[1].position";
    QTest::newRow("overlap") << "balls.1.x" << "1.23" << "balls[1].position";
    QTest::newRow("zero mass") << "balls.cue.mass" << "0" << "balls[0].mass";
    QTest::newRow("elevation") << "shot.elevation" << "95" << "shot.elevation";
}

void TestOverride::illegalOverrideIsRefused()
{
    QFETCH(QString, key);
    QFETCH(QString, value);
    QFETCH(QString, path);
    Setup setup = test::example("half-ball-cut.json");
    QVERIFY(!applyOverride(setup, key.toStdString(), value.toStdString()));
    const auto problem = firstSetupProblem(setup);
    QVERIFY(problem);
    QCOMPARE(QString::fromStdString(problem->path), path);
    const QString message = QString::fromStdString(refusalMessage("cut.json", *problem));
    QVERIFY2(message.startsWith(QStringLiteral("cut.json: ") + path + QStringLiteral(": ")), qPrintable(message));
}

void TestOverride::assignmentAndNumbers()
{
    QCOMPARE(parseAssignment("shot.speed=3")->key, std::string("shot.speed"));
    QCOMPARE(parseAssignment("a=b=c")->value, std::string("b=c"));
    QVERIFY(!parseAssignment("shot.speed"));
    QVERIFY(!parseAssignment("=3"));
    QCOMPARE(*parseNumber("+2"), 2.0);
    QCOMPARE(*parseNumber("-0.5"), -0.5);
    QCOMPARE(*parseNumber("1e-3"), 1e-3);
    QVERIFY(!parseNumber("++2"));
    QVERIFY(!parseNumber(" 2"));
    QVERIFY(!parseNumber("0x10"));
}

void TestOverride::everyListedKeyResolves()
{
    const Setup setup = test::example("half-ball-cut.json");
    const auto keys = overridableKeys(setup, false);
    // 24 keys of issue 11, shot.end_mass, name and notes (han2005 has no parameters of its own), 9 per ball
    QCOMPARE(static_cast<int>(keys.size()), 27 + 2 * 9);
    for (const std::string& key : keys) QVERIFY2(std::holds_alternative<Parameter>(Parameter::resolve(setup, key)), key.c_str());
    Setup noShot = setup;
    noShot.shot.reset();
    QVERIFY(std::holds_alternative<OverrideError>(Parameter::resolve(noShot, "shot.speed")));
}

// physics.ball_cushion.model takes every name of the registry (CushionModels.cpp), as a file does.
void TestOverride::everyRegisteredModel()
{
    QVERIFY(cushionModels().size() >= 4);
    for (const CushionModelEntry& e : cushionModels()) {
        Setup setup = test::example("half-ball-cut.json");
        QVERIFY2(!applyOverride(setup, "physics.ball_cushion.model", e.name), std::string(e.name).c_str());
        QVERIFY(setup.physics.ballCushionModel == e.model);
        auto p = Parameter::resolve(setup, "physics.ball_cushion.model");
        QCOMPARE(std::get<Parameter>(p).text(setup), std::string(e.name));
    }
    // The refusal lists them, in the registry's order.
    Setup setup = test::example("half-ball-cut.json");
    const auto error = applyOverride(setup, "physics.ball_cushion.model", "strong");
    QVERIFY(error && error->kind == OverrideError::Kind::BadValue);
    QCOMPARE(error->message, std::string("physics.ball_cushion.model: expected mirror, han2005, mathavan2010 or stronge, found \"strong\""));
}

// Each model's own parameters are keys while that model is chosen; with another model the key says
// whose it is (a file refuses it then too).
void TestOverride::modelParametersFromTheRegistry()
{
    for (const CushionModelEntry& e : cushionModels()) {
        for (const CushionModelParameter& q : e.parameters) {
            const std::string key = "physics.ball_cushion." + std::string(q.key);
            Setup setup = test::example("half-ball-cut.json");  // han2005
            const auto wrongModel = applyOverride(setup, key, "1.5");
            QVERIFY2(wrongModel && wrongModel->kind == OverrideError::Kind::UnknownKey, key.c_str());
            QVERIFY2(wrongModel->message.find("set physics.ball_cushion.model=" + std::string(e.name) + " first") != std::string::npos,
                     wrongModel->message.c_str());
            QVERIFY(!applyOverride(setup, "physics.ball_cushion.model", e.name));
            const auto keys = overridableKeys(setup, true);
            QVERIFY2(std::find(keys.begin(), keys.end(), key) != keys.end(), key.c_str());
            // A value inside the parameter's range: the middle of it, a whole number for a whole one.
            const double value = q.integer ? std::floor((q.min + q.max) / 2.0) : (q.min + q.max) / 2.0;
            QVERIFY(!applyOverride(setup, key, roundTrip(value)));
            QCOMPARE(setup.physics.*(q.field), value);
            QVERIFY(!firstSetupProblem(setup));
            // Beyond the range: the validator refuses it with the file's message.
            QVERIFY(!applyOverride(setup, key, roundTrip(q.max + 1.0)));
            const auto problem = firstSetupProblem(setup);
            QVERIFY(problem);
            QCOMPARE(problem->path, key);
        }
    }
}

void TestOverride::unknownKeyListsTheValidOnes()
{
    Setup setup = test::example("half-ball-cut.json");
    const auto error = applyOverride(setup, "shot.sped", "1");
    QVERIFY(error);
    for (const char* key : {"shot.speed", "shot.end_mass", "physics.ball_cushion.model", "table.kind", "simulation.max_time",
                            "name", "balls.<id>.x|y|vx|vy|wx|wy|wz|radius|mass with <id> one of cue, 1"})
        QVERIFY2(error->message.find(key) != std::string::npos, (std::string(key) + " in " + error->message).c_str());
    const auto noBall = applyOverride(setup, "balls.9.x", "1");
    QVERIFY(noBall);
    QVERIFY2(noBall->message.find("the balls are \"cue\", \"1\"") != std::string::npos, noBall->message.c_str());
}

// docs/analysis.md's key table names every registered model and every model parameter's key, so the
// page follows the registry (a new model without its row fails here).
void TestOverride::docsListEveryModelAndParameter()
{
    QFile file(QStringLiteral(CUELAB_SOURCE_DIR "/docs/analysis.md"));
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(file.readAll());
    for (const CushionModelEntry& e : cushionModels()) {
        QVERIFY2(text.contains(QStringLiteral("`%1`").arg(QString::fromUtf8(e.name.data(), static_cast<int>(e.name.size())))),
                 std::string(e.name).c_str());
        for (const CushionModelParameter& q : e.parameters)
            QVERIFY2(text.contains(QStringLiteral("`physics.ball_cushion.%1`").arg(QString::fromUtf8(q.key.data(), static_cast<int>(q.key.size())))),
                     std::string(q.key).c_str());
    }
    QVERIFY(text.contains(QStringLiteral("`shot.end_mass`")));
}

QTEST_GUILESS_MAIN(TestOverride)
#include "tst_override.moc"
