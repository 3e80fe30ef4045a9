// Shot codes (CONTRACT.md, Extensions version 3; core/io/ShotCode.h) and the table kinds' own cloth
// ("Table kinds bring their own cloth", core/setup/KindDefaults.h).
//  - every bundled example goes to a code and back bit for bit, and simulates to the same events;
//  - a 16-ball setup with default physics fits in 600 characters, even with every position at full
//    precision;
//  - broken codes are refused with the problem named, never half-loaded;
//  - codes made by this version are pinned: they must keep meaning the same setup (the physics left
//    out of a version-1 code is the defaults of today);
//  - a carom setup that leaves its cloth out gets carom cloth; pool keeps the pool defaults.

#include "KindDefaults.h"
#include "SetupCompare.h"
#include "SetupFile.h"
#include "ShotCode.h"
#include "Simulation.h"

#include <QDir>
#include <QFile>
#include <QRandomGenerator>
#include <QtTest>

using namespace cuelab;

namespace {

Setup load(const QString& path)
{
    QString error;
    const std::optional<Setup> setup = io::loadSetup(path, &error);
    if (!setup) qFatal("%s", qPrintable(error));
    return *setup;
}

Setup parse(const QByteArray& json)
{
    QString error;
    const std::optional<Setup> setup = io::parseSetup(json, QStringLiteral("test.json"), &error);
    if (!setup) qFatal("%s", qPrintable(error));
    return *setup;
}

QString refusal(const QString& code)
{
    QString error;
    const std::optional<Setup> setup = io::parseShotCode(code, &error);
    return setup ? QString() : error;
}

}  // namespace

class ShotCodeTest : public QObject {
    Q_OBJECT
private slots:
    void examplesRoundTripBitForBit_data()
    {
        QTest::addColumn<QString>("path");
        const QDir dir(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples"));
        for (const QString& name : dir.entryList({QStringLiteral("*.json")}, QDir::Files))
            QTest::newRow(qPrintable(name)) << dir.filePath(name);
    }
    void examplesRoundTripBitForBit()
    {
        QFETCH(QString, path);
        const Setup original = load(path);
        const QString code = io::shotCode(original);
        QVERIFY(code.startsWith(QLatin1String("cuelab:1:")));
        QVERIFY2(!code.contains(QLatin1Char(' ')) && !code.contains(QLatin1Char('=')) && !code.contains(QLatin1Char('+')) &&
                     !code.contains(QLatin1Char('/')),
                 "a code is URL-safe base64 without padding");
        QString error;
        const std::optional<Setup> back = io::parseShotCode(code, &error);
        QVERIFY2(back, qPrintable(error));
        const QStringList setupDiff = testing::setupDifferences(original, *back);
        QVERIFY2(setupDiff.isEmpty(), qPrintable(setupDiff.join(QStringLiteral(", "))));
        // The same text as a file, and the same events bit for bit.
        QCOMPARE(io::serializeSetup(*back), io::serializeSetup(original));
        const QStringList eventDiff = testing::eventLogDifferences(simulate(original), simulate(*back));
        QVERIFY2(eventDiff.isEmpty(), qPrintable(eventDiff.join(QStringLiteral(", "))));
        // A code is taken wherever a path is.
        const std::optional<Setup> viaPath = io::loadSetup(code, &error);
        QVERIFY2(viaPath, qPrintable(error));
        QVERIFY(testing::setupDifferences(original, *viaPath).isEmpty());
    }

    void sixteenBallsFitIn600Characters()
    {
        Setup rack = load(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/8-ball-break.json"));
        rack.notes.clear();  // the lesson's prose is the user's to share or not; the layout is the code's
        QCOMPARE(rack.balls.size(), std::size_t{16});
        const QString code = io::shotCode(rack);
        QVERIFY2(code.size() <= 600, qPrintable(QString::number(code.size())));
        // The worst case: every coordinate a random double with all 17 digits (the rack spread by 1 %
        // about its apex so that no two balls touch, each ball then moved by up to 0.1 mm).
        QRandomGenerator random(20261207);
        Setup spread = rack;
        const Vec2 apex = spread.balls[1].state.position;
        for (Ball& b : spread.balls) {
            const Vec2 jitter(random.bounded(2e-4) - 1e-4, random.bounded(2e-4) - 1e-4);
            b.state.position = apex + 1.01 * (b.state.position - apex) + jitter;
        }
        QString error;
        QVERIFY2(io::parseSetup(io::serializeSetup(spread), QStringLiteral("spread.json"), &error), qPrintable(error));
        const QString worst = io::shotCode(spread);
        QVERIFY2(worst.size() <= 600, qPrintable(QString::number(worst.size())));
        const std::optional<Setup> back = io::parseShotCode(worst, &error);
        QVERIFY2(back, qPrintable(error));
        QVERIFY(testing::setupDifferences(spread, *back).isEmpty());
    }

    void physicsOtherThanTheDefaultsTravels()
    {
        Setup setup = load(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json"));
        setup.physics.muRoll = 0.0123456789012345;
        setup.physics.ballCushionModel = BallCushionModel::Mathavan2010;
        setup.physics.mathavanSteps = 2000.0;
        setup.physics.ballBallModel = BallBallModel::Frictional;
        setup.physics.ballBallFrictionKind = BallBallFriction::Alciatore;
        QString error;
        const std::optional<Setup> back = io::parseShotCode(io::shotCode(setup), &error);
        QVERIFY2(back, qPrintable(error));
        const QStringList diff = testing::setupDifferences(setup, *back);
        QVERIFY2(diff.isEmpty(), qPrintable(diff.join(QStringLiteral(", "))));
    }

    void brokenCodesAreRefusedWithTheProblemNamed()
    {
        const QString good = io::shotCode(load(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/straight-shot.json")));
        QVERIFY(refusal(good).isEmpty());
        const struct {
            QString code;
            const char* says;
        } cases[] = {
            {QStringLiteral("cuelab:"), "no version"},
            {QStringLiteral("cuelab:x:abc"), "no version number"},
            {QStringLiteral("cuelab:2:") + good.mid(9), "version 2 is not known"},
            {QStringLiteral("cuelab:1:"), "empty"},
            {QStringLiteral("cuelab:1:ab*cd"), "not URL-safe base64"},
            {QStringLiteral("cuelab:1:AAAA"), "too short"},
            {QStringLiteral("cuelab:1:AAAAAAAA"), "does not unpack"},
            {good.left(good.size() / 2), "broken: "},
            {good.left(good.size() - 3), "broken: "},
            // A code whose text is no setup (a JSON array) and one whose setup the loader refuses.
            {QStringLiteral("cuelab:1:") +
                 io::shotCodeOfText("[1,2]").mid(9),
             "does not hold a setup"},
            {QStringLiteral("cuelab:1:") +
                 io::shotCodeOfText("{\"version\":1,\"balls\":[{\"id\":\"cue\",\"position\":[9,9]}]}").mid(9),
             "balls"},
        };
        for (const auto& c : cases) {
            const QString message = refusal(c.code);
            QVERIFY2(message.startsWith(QLatin1String("shot code: ")), qPrintable(c.code + QLatin1String(" -> ") + message));
            QVERIFY2(message.contains(QLatin1String(c.says)), qPrintable(c.code + QLatin1String(" -> ") + message));
        }
        // One changed character anywhere: refused (the code's CRC-32), never read as another setup.
        for (qsizetype i = 9; i < good.size(); ++i) {
            QString other = good;
            other[i] = good[i] == QLatin1Char('A') ? QLatin1Char('B') : QLatin1Char('A');
            QVERIFY2(!refusal(other).isEmpty(), qPrintable(QString::number(i)));
        }
        QString changed = good;
        const qsizetype middle = good.size() / 2;
        changed[middle] = good[middle] == QLatin1Char('A') ? QLatin1Char('B') : QLatin1Char('A');
        QVERIFY(!refusal(changed).isEmpty());
        // Surrounding spaces and a line break, as a chat adds them, are fine.
        QVERIFY(refusal(QStringLiteral("  ") + good + QStringLiteral("\n")).isEmpty());
    }

    // Codes made by version 1 of the writer: they must keep their meaning. Each leaves the physics out
    // (the defaults of its table kind); a change of those defaults must come with a new code version.
    void pinnedCodesKeepTheirMeaning()
    {
        QString error;
        const std::optional<Setup> carom = io::parseShotCode(QStringLiteral(
            "cuelab:1:w1CDJdEBMzjQ-yZA7-NJs4bA4sJAzxyhCCONguSNwUGEFhowK4HOi4eVzqZm5jgDyAh_CBnX4q8OzNAAcvVgZmCAJXwhxYcOtCYDuq-kqDQVNawBP6tiuQ"),
            &error);
        QVERIFY2(carom, qPrintable(error));
        QVERIFY(carom->table.kind == TableKind::Carom);
        QCOMPARE(carom->balls.size(), std::size_t{3});
        QCOMPARE(carom->balls[2].id, std::string("red"));
        QCOMPARE(carom->balls[1].state.position, Vec2(1.2, 0.7));
        QCOMPARE(carom->shot->headingDeg, 20.0);
        QCOMPARE(carom->physics.muRoll, 0.00453);
        QCOMPARE(carom->physics.muSlide, 0.1905);
        QCOMPARE(carom->physics.muSpin, 0.01232);
        QCOMPARE(carom->physics.cushionRestitution, 0.8476);
        QCOMPARE(carom->physics.cushionFriction, 0.1991);
        QCOMPARE(carom->physics.ballBallRestitution, 0.95);
        QVERIFY(carom->physics.ballCushionModel == BallCushionModel::Han2005);

        const std::optional<Setup> pool = io::parseShotCode(QStringLiteral(
            "cuelab:1:I0aNGdTzuALHAihvDvY7Vm8CyXhYoWtqZo7T3yZI_tYzxu5zfMW8GRpALvbNDAzwhZsOtJICurGkqDQVNRgBBrzJxA"),
            &error);
        QVERIFY2(pool, qPrintable(error));
        QVERIFY(pool->table.kind == TableKind::Pool9ft);
        QCOMPARE(pool->shot->height, 0.3);
        const PhysicsParams d;
        QCOMPARE(pool->physics.muRoll, d.muRoll);
        QCOMPARE(pool->physics.muRoll, 0.01);
        QCOMPARE(pool->physics.muSlide, 0.2);
        QCOMPARE(pool->physics.muSpin, 0.0127);
        QCOMPARE(pool->physics.cushionRestitution, 0.85);
        QCOMPARE(pool->physics.cushionFriction, 0.2);
        QCOMPARE(pool->physics.ballBallRestitution, 0.95);
        QCOMPARE(pool->physics.gravity, 9.81);
    }

    void tableKindsBringTheirOwnCloth()
    {
        const QByteArray carom = "{\"format\":\"cuelab-setup\",\"version\":1,\"table\":{\"kind\":\"carom\"}, \"balls\":[{\"id\":\"white\",\"position\":[0.5,0.4]}]}";
        const Setup c = parse(carom);
        QCOMPARE(c.physics.muRoll, 0.00453);
        QCOMPARE(c.physics.muSlide, 0.1905);
        QCOMPARE(c.physics.cushionRestitution, 0.8476);
        QVERIFY(hasKindCloth(c.physics, TableKind::Carom));
        // A key given is the file's; the others still the kind's.
        const Setup given = parse("{\"format\":\"cuelab-setup\",\"version\":1,\"table\":{\"kind\":\"carom\"}, \"physics\":{\"mu_roll\":0.01,\"ball_cushion\":{\"model\":\"mirror\"}},\"balls\":[{\"id\":\"white\",\"position\":[0.5,0.4]}]}");
        QCOMPARE(given.physics.muRoll, 0.01);
        QCOMPARE(given.physics.muSlide, 0.1905);
        QCOMPARE(given.physics.cushionRestitution, 0.8476);
        QVERIFY(given.physics.ballCushionModel == BallCushionModel::Mirror);
        // Pool and snooker keep PHYSICS.md's defaults.
        for (const char* kind : {"pool-9ft", "pool-8ft", "pool-7ft", "snooker"}) {
            const Setup p = parse(QByteArray("{\"format\":\"cuelab-setup\",\"version\":1,\"table\":{\"kind\":\"") + kind +
                                  "\"},\"balls\":[{\"id\":\"cue\",\"position\":[0.5,0.4]}]}");
            QCOMPARE(p.physics.muRoll, PhysicsParams().muRoll);
            QCOMPARE(p.physics.muSlide, PhysicsParams().muSlide);
            QCOMPARE(p.physics.cushionRestitution, PhysicsParams().cushionRestitution);
        }
        // A file written with every value keeps them: the pool cloth on a carom table stays.
        Setup poolCloth = c;
        poolCloth.physics = PhysicsParams();
        const Setup back = parse(io::serializeSetup(poolCloth));
        QCOMPARE(back.physics.muRoll, 0.01);
        QVERIFY(!hasKindCloth(back.physics, TableKind::Carom));
        // setKindCloth swaps the cloth and nothing else.
        PhysicsParams p;
        p.gravity = 9.80665;
        setKindCloth(p, TableKind::Carom);
        QVERIFY(hasKindCloth(p, TableKind::Carom));
        QCOMPARE(p.gravity, 9.80665);
        setKindCloth(p, TableKind::Pool9ft);
        QVERIFY(hasKindCloth(p, TableKind::Pool9ft));
    }
};

QTEST_MAIN(ShotCodeTest)
#include "tst_shotcode.moc"
