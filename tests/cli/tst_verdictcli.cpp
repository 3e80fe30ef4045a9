// The verdict of a game's rules through cuelab-cli (CONTRACT.md, Extensions version 3): `simulate`'s
// outcome gains "verdict" only with a game, --set game.* sets one, a ball that does not fit the game
// is refused by name, and the goal terms of the rules need a game.

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

namespace {

const QString kBinary = QStringLiteral(CUELAB_BINARY_DIR "/bin/cuelab-cli");
const QString kStraight = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/straight-shot.json");

struct Run {
    int status = -1;
    QByteArray out;
    QByteArray err;
};

Run cli(const QStringList& arguments)
{
    QProcess process;
    process.start(kBinary, arguments);
    if (!process.waitForFinished(120000)) qFatal("cuelab-cli did not finish: %s", qPrintable(arguments.join(' ')));
    Run r;
    r.status = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    r.out = process.readAllStandardOutput();
    r.err = process.readAllStandardError();
    return r;
}

QJsonObject outcomeOf(const Run& r)
{
    return QJsonDocument::fromJson(r.out).object().value(QStringLiteral("outcome")).toObject();
}

}  // namespace

class TestVerdictCli : public QObject {
    Q_OBJECT

private slots:
    void noGameNoVerdict()
    {
        const Run r = cli({"simulate", kStraight});
        QCOMPARE(r.status, 0);
        QVERIFY(!outcomeOf(r).contains(QStringLiteral("verdict")));
        QVERIFY(!r.out.contains("verdict"));
    }

    // The straight shot pots the 1 in the top-right pocket and the cue ball stays up: legal, the 1
    // scored, the striker plays on; the deciding event is the 1's ball-pocket event.
    void legalPotIn9Ball()
    {
        const Run r = cli({"simulate", kStraight, "--set", "game.rules=9-ball"});
        QCOMPARE(r.status, 0);
        const QJsonObject document = QJsonDocument::fromJson(r.out).object();
        const QJsonObject v = document.value(QStringLiteral("outcome")).toObject().value(QStringLiteral("verdict")).toObject();
        QCOMPARE(v.value(QStringLiteral("rules")).toString(), QStringLiteral("9-ball"));
        QCOMPARE(v.value(QStringLiteral("legal")).toBool(), true);
        QVERIFY(v.value(QStringLiteral("foul")).isNull());
        QCOMPARE(v.value(QStringLiteral("scored")).toArray(), QJsonArray{QStringLiteral("1")});
        QCOMPARE(v.value(QStringLiteral("points")).toInt(-1), 0);
        QCOMPARE(v.value(QStringLiteral("foul_points")).toInt(-1), 0);
        QCOMPARE(v.value(QStringLiteral("continues")).toBool(), true);
        QCOMPARE(v.value(QStringLiteral("ball_in_hand")).toBool(), false);
        QCOMPARE(v.value(QStringLiteral("respotted")).toArray(), QJsonArray{});
        const int event = v.value(QStringLiteral("event")).toInt(-1);
        const QJsonObject decided = document.value(QStringLiteral("events")).toArray().at(event).toObject();
        QCOMPARE(decided.value(QStringLiteral("type")).toString(), QStringLiteral("ball-pocket"));
        QCOMPARE(decided.value(QStringLiteral("balls")).toArray(), QJsonArray{QStringLiteral("1")});
        QCOMPARE(v.value(QStringLiteral("text")).toString(), QStringLiteral("legal: 1 pocketed; the striker plays on"));
        // Deterministic: the same input, the same bytes.
        QCOMPARE(cli({"simulate", kStraight, "--set", "game.rules=9-ball"}).out, r.out);
    }

    // Faster, the cue ball follows the 1 into the pocket (the example's notes say so): a scratch.
    void scratchIn9Ball()
    {
        const Run r = cli({"simulate", kStraight, "--set", "game.rules=9-ball", "--set", "shot.speed=1.2"});
        QCOMPARE(r.status, 0);
        const QJsonObject v = outcomeOf(r).value(QStringLiteral("verdict")).toObject();
        QCOMPARE(v.value(QStringLiteral("legal")).toBool(), false);
        const QJsonObject foul = v.value(QStringLiteral("foul")).toObject();
        QCOMPARE(foul.value(QStringLiteral("rule")).toString(), QStringLiteral("scratch"));
        QCOMPARE(foul.value(QStringLiteral("text")).toString(), QStringLiteral("the cue ball fell into pocket-tr"));
        QCOMPARE(v.value(QStringLiteral("ball_in_hand")).toBool(), true);
        QCOMPARE(v.value(QStringLiteral("scored")).toArray(), QJsonArray{});
    }

    void refusalsAndUsage_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<int>("status");
        QTest::addColumn<QString>("message");
        QTest::newRow("ball not of snooker") << QStringList{"simulate", kStraight, "--set", "game.rules=snooker"} << 1
                                             << "straight-shot.json: balls[1].id: ball \"1\" is not a ball of snooker";
        QTest::newRow("unknown rules") << QStringList{"simulate", kStraight, "--set", "game.rules=pool"} << 2
                                       << "game.rules: expected 8-ball, 9-ball, 10-ball, snooker or three-cushion (or none), found \"pool\"";
        QTest::newRow("group without a game") << QStringList{"simulate", kStraight, "--set", "game.group=solids"} << 2
                                              << "set game.rules first";
        QTest::newRow("legal without a game")
            << QStringList{"odds", kStraight, "--goal", "legal", "--noise", "shot.heading=0.1", "--samples", "4"} << 2
            << "legal needs the rules of a game";
    }
    void refusalsAndUsage()
    {
        QFETCH(QStringList, arguments);
        QFETCH(int, status);
        QFETCH(QString, message);
        const Run r = cli(arguments);
        QCOMPARE(r.status, status);
        QVERIFY2(QString::fromUtf8(r.err).contains(message), r.err.constData());
    }

    void oddsOfALegalShot()
    {
        const Run r = cli({"odds", kStraight, "--set", "game.rules=9-ball", "--goal", "scores", "--noise", "shot.heading=0.0001",
                           "--samples", "8", "--seed", "1"});
        QCOMPARE(r.status, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o.value(QStringLiteral("successes")).toInt(-1), 8);
    }
};

QTEST_GUILESS_MAIN(TestVerdictCli)
#include "tst_verdictcli.moc"
