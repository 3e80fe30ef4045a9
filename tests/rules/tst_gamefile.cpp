// The setup file's "game" (CONTRACT.md, Extensions version 3): read and written back unchanged, a
// file without it written as before, refused with the ball or key named, set with --set, and the
// goal terms of the rules (legal, scores, point) on simulated shots.

#include "Goal.h"
#include "LegalSetup.h"
#include "Override.h"
#include "SetupFile.h"
#include "Sweep.h"
#include "Verdict.h"

#include <QTest>

using namespace cuelab;

namespace {

QByteArray setupText(const QByteArray& balls, const QByteArray& game, const QByteArray& table = "pool-9ft")
{
    return "{\"format\": \"cuelab-setup\", \"version\": 1, \"table\": {\"kind\": \"" + table + "\"},\n"
           "\"balls\": [" + balls + "],\n"
           "\"shot\": {\"ball\": \"cue\", \"speed\": 2, \"heading\": 0, \"elevation\": 0, \"side\": 0, \"height\": 0}" +
           (game.isEmpty() ? QByteArray() : ",\n\"game\": " + game) + "}";
}

// The cue ball straight behind the 1 on the table's long axis: shot along it, the 1 meets the foot
// rail in its middle, far from any pocket.
const QByteArray kPoolBalls = "{\"id\": \"cue\", \"position\": [0.6, 0.635]}, {\"id\": \"1\", \"position\": [1.2, 0.635]}";

Setup parse(const QByteArray& text)
{
    QString error;
    const std::optional<Setup> setup = io::parseSetup(text, QStringLiteral("rack.json"), &error);
    if (!setup) qFatal("%s", qPrintable(error));
    return *setup;
}

QString refusal(const QByteArray& text)
{
    QString error;
    const std::optional<Setup> setup = io::parseSetup(text, QStringLiteral("rack.json"), &error);
    return setup ? QString() : error;
}

}  // namespace

class TestGameFile : public QObject {
    Q_OBJECT

private slots:
    void roundTrip_data()
    {
        QTest::addColumn<QByteArray>("game");
        QTest::newRow("9-ball") << QByteArray("{\"rules\": \"9-ball\"}");
        QTest::newRow("8-ball, every key") << QByteArray("{\"rules\": \"8-ball\", \"group\": \"stripes\", \"nominated\": \"pocket-tr\", \"break\": true}");
        QTest::newRow("10-ball break") << QByteArray("{\"rules\": \"10-ball\", \"break\": true}");
    }
    void roundTrip()
    {
        QFETCH(QByteArray, game);
        const Setup setup = parse(setupText(kPoolBalls, game));
        QVERIFY(setup.game.has_value());
        const QByteArray saved = io::serializeSetup(setup);
        QVERIFY(saved.contains("\"game\": "));
        const Setup again = parse(saved);
        QVERIFY(again.game.has_value());
        QVERIFY(again.game->rules == setup.game->rules);
        QVERIFY(again.game->group == setup.game->group);
        QVERIFY(again.game->on == setup.game->on);
        QCOMPARE(again.game->nominated, setup.game->nominated);
        QCOMPARE(again.game->breakShot, setup.game->breakShot);
        QCOMPARE(io::serializeSetup(again), saved);
    }

    void snookerAndCaromRoundTrip()
    {
        const Setup snooker = parse(setupText("{\"id\": \"cue\", \"position\": [0.6, 0.9]}, {\"id\": \"red-1\", \"position\": [2.5, 0.9]}",
                                              "{\"rules\": \"snooker\", \"on\": \"colour\"}", "snooker"));
        QVERIFY(snooker.game && snooker.game->on == SnookerOn::Colour);
        QVERIFY(io::serializeSetup(snooker).contains("\"game\": { \"rules\": \"snooker\", \"on\": \"colour\" }"));
    }

    // A file without a game reads and writes as it always did: no key appears.
    void withoutGameNothingChanges()
    {
        const Setup setup = parse(setupText(kPoolBalls, {}));
        QVERIFY(!setup.game);
        QVERIFY(!io::serializeSetup(setup).contains("game"));
    }

    void refusals_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown rules") << setupText(kPoolBalls, "{\"rules\": \"straight-pool\"}")
                                       << "rack.json: game.rules: unknown rules \"straight-pool\" (expected 8-ball, 9-ball, 10-ball, snooker or three-cushion)";
        QTest::newRow("rules missing") << setupText(kPoolBalls, "{\"group\": \"open\"}") << "rack.json: game.rules: required key is missing";
        QTest::newRow("unknown group") << setupText(kPoolBalls, "{\"rules\": \"8-ball\", \"group\": \"spots\"}")
                                       << "rack.json: game.group: unknown group \"spots\" (expected open, solids or stripes)";
        QTest::newRow("unknown on") << setupText(kPoolBalls, "{\"rules\": \"snooker\", \"on\": \"purple\"}")
                                    << "rack.json: game.on: unknown ball on \"purple\" (expected red, colour, yellow, green, brown, blue, pink or black)";
        QTest::newRow("unknown key") << setupText(kPoolBalls, "{\"rules\": \"9-ball\", \"call\": \"pocket-tr\"}")
                                     << "rack.json: game.call: unknown key (expected one of: rules, group, on, nominated, break)";
        QTest::newRow("group in 9-ball") << setupText(kPoolBalls, "{\"rules\": \"9-ball\", \"group\": \"solids\"}")
                                         << "rack.json: game.group: a group belongs to 8-ball, not to 9-ball";
        QTest::newRow("no such pocket") << setupText(kPoolBalls, "{\"rules\": \"9-ball\", \"nominated\": \"pocket-x\"}")
                                        << "rack.json: game.nominated: the table has no pocket \"pocket-x\"";
        QTest::newRow("ball not of 9-ball")
            << setupText(kPoolBalls + ", {\"id\": \"12\", \"position\": [2.0, 0.3]}", "{\"rules\": \"9-ball\"}")
            << "rack.json: balls[2].id: ball \"12\" is not a ball of 9-ball (its balls are cue and 1 to 9)";
        QTest::newRow("ball not of snooker")
            << setupText("{\"id\": \"cue\", \"position\": [0.6, 0.9]}, {\"id\": \"7\", \"position\": [2.5, 0.9]}", "{\"rules\": \"snooker\"}", "snooker")
            << "rack.json: balls[1].id: ball \"7\" is not a ball of snooker (its balls are cue, red-<n>, yellow, green, brown, blue, pink and black)";
        QTest::newRow("three-cushion with two balls")
            << setupText(kPoolBalls, "{\"rules\": \"three-cushion\"}", "carom")
            << "rack.json: balls: three-cushion is played with three balls; the setup has 2";
    }
    void refusals()
    {
        QFETCH(QByteArray, text);
        QFETCH(QString, message);
        QCOMPARE(refusal(text), message);
    }

    void setKeys()
    {
        Setup setup = parse(setupText(kPoolBalls, {}));
        // Without a game its keys are not listed, and only game.rules resolves.
        for (const std::string& key : analysis::overridableKeys(setup, false)) QVERIFY(key.rfind("game.", 0) != 0);
        const auto noGame = analysis::applyOverride(setup, "game.group", "solids");
        QVERIFY(noGame && noGame->kind == analysis::OverrideError::Kind::UnknownKey);
        QVERIFY(!analysis::applyOverride(setup, "game.rules", "8-ball"));
        QVERIFY(setup.game && setup.game->rules == GameRules::EightBall);
        QVERIFY(!analysis::applyOverride(setup, "game.group", "stripes"));
        QVERIFY(setup.game->group == PoolGroup::Stripes);
        QVERIFY(!analysis::applyOverride(setup, "game.nominated", "pocket-b"));
        QCOMPARE(setup.game->nominated, std::string("pocket-b"));
        QVERIFY(!analysis::applyOverride(setup, "game.break", "true"));
        QVERIFY(setup.game->breakShot);
        const auto bad = analysis::applyOverride(setup, "game.group", "spots");
        QVERIFY(bad && bad->kind == analysis::OverrideError::Kind::BadValue);
        QCOMPARE(QString::fromStdString(bad->message), QStringLiteral("game.group: expected open, solids or stripes, found \"spots\""));
        // A change of rules drops the keys the new rules do not have.
        QVERIFY(!analysis::applyOverride(setup, "game.rules", "9-ball"));
        QVERIFY(!setup.game->group);
        QVERIFY(setup.game->breakShot);
        QVERIFY(!firstSetupProblem(setup));
        // The ball that does not fit is named when the override makes the setup illegal.
        Setup carom = setup;
        QVERIFY(!analysis::applyOverride(carom, "game.rules", "snooker"));
        const std::optional<SetupProblem> problem = firstSetupProblem(carom);
        QVERIFY(problem);
        QCOMPARE(QString::fromStdString(problem->path), QStringLiteral("balls[1].id"));
        QCOMPARE(QString::fromStdString(problem->ballId), QStringLiteral("1"));
        QVERIFY(!analysis::applyOverride(setup, "game.rules", "none"));
        QVERIFY(!setup.game);
        const auto unknown = analysis::applyOverride(setup, "game.rules", "pool");
        QVERIFY(unknown && unknown->kind == analysis::OverrideError::Kind::BadValue);
    }

    void goalTerms()
    {
        for (const char* text : {"legal", "scores", "point", "!legal", "legal,pot:1"}) {
            const auto goal = analysis::parseGoal(text);
            QVERIFY2(std::holds_alternative<analysis::Goal>(goal), text);
            QCOMPARE(QString::fromStdString(analysis::goalText(std::get<analysis::Goal>(goal))), QString::fromUtf8(text));
        }
        QVERIFY(std::holds_alternative<std::string>(analysis::parseGoal("legal:1")));
        QCOMPARE(analysis::describeGoal(std::get<analysis::Goal>(analysis::parseGoal("legal,scores"))),
                 std::string("a legal shot, the striker plays on"));

        // Terms of the rules need a game, and point needs three-cushion.
        Setup setup = parse(setupText(kPoolBalls, {}));
        std::string error;
        QVERIFY(!analysis::ResolvedGoal::resolve(std::get<analysis::Goal>(analysis::parseGoal("legal")), setup, &error));
        QVERIFY2(error.find("needs the rules of a game") != std::string::npos, error.c_str());
        setup.game = GameSpec{GameRules::NineBall, {}, {}, {}, false};
        QVERIFY(!analysis::ResolvedGoal::resolve(std::get<analysis::Goal>(analysis::parseGoal("point")), setup, &error));
        QVERIFY2(error.find("three-cushion") != std::string::npos, error.c_str());
    }

    // Goals on simulated shots through the sweep: the firm straight shot drives the 1 into the foot
    // rail (legal, nothing down, the turn passes); a shot at 90° runs across the table and back, beside the 1 (no contact: a foul).
    void goalsOnSimulatedShots_data()
    {
        QTest::addColumn<double>("heading");
        QTest::addColumn<QString>("goal");
        QTest::addColumn<bool>("met");
        QTest::newRow("straight: legal") << 0.0 << "legal" << true;
        QTest::newRow("straight: does not score") << 0.0 << "scores" << false;
        QTest::newRow("straight: not a foul") << 0.0 << "!legal" << false;
        QTest::newRow("away: a foul") << 90.0 << "legal" << false;
        QTest::newRow("away: !legal") << 90.0 << "!legal" << true;
    }
    void goalsOnSimulatedShots()
    {
        QFETCH(double, heading);
        QFETCH(QString, goal);
        QFETCH(bool, met);
        analysis::SweepSpec spec;
        spec.base = parse(setupText(kPoolBalls, "{\"rules\": \"9-ball\"}"));
        spec.base.shot->headingDeg = heading;
        std::string error;
        const auto resolved = analysis::ResolvedGoal::resolve(std::get<analysis::Goal>(analysis::parseGoal(goal.toStdString())), spec.base, &error);
        QVERIFY2(resolved, error.c_str());
        spec.goal = *resolved;
        const analysis::ShotResult shot = analysis::runShotWith(spec, {});
        QVERIFY(shot.status == analysis::ShotStatus::Simulated);
        QCOMPARE(shot.goalMet, met);
    }
};

QTEST_GUILESS_MAIN(TestGameFile)
#include "tst_gamefile.moc"
