// cuelab-cli's Extensions of issue 11 (CONTRACT.md): `--set KEY=VALUE` on every subcommand, `-` for
// standard input, and `sweep --vary ... [--shard K/N] [--jobs J]`. Sweep lines equal single
// `simulate --set` runs; one thread and all give identical output; shards concatenate to the whole;
// bad input is a usage error naming the culprit; an illegal combination is one refused line.

#include "Cli.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

#include <algorithm>
#include <map>

namespace {

const QString kBinary = QStringLiteral(CUELAB_BINARY_DIR "/bin/cuelab-cli");
const QString kCut = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json");

struct Run {
    int status = -1;
    QByteArray out;
    QByteArray err;
};

// In process, through the same entry point as the program.
Run cli(QStringList arguments)
{
    arguments.prepend(QStringLiteral("cuelab-cli"));
    Run r;
    r.status = cuelab::cli::run(arguments, &r.out, &r.err);
    return r;
}

// As a program, with `input` on standard input.
Run program(const QStringList& arguments, const QByteArray& input)
{
    QProcess process;
    process.start(kBinary, arguments);
    process.write(input);
    process.closeWriteChannel();
    if (!process.waitForFinished(120000)) qFatal("cuelab-cli did not finish");
    return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1, process.readAllStandardOutput(),
            process.readAllStandardError()};
}

QJsonObject object(const QByteArray& text)
{
    QJsonParseError error;
    const QJsonDocument d = QJsonDocument::fromJson(text, &error);
    if (error.error != QJsonParseError::NoError || !d.isObject()) qFatal("not JSON: %s", text.constData());
    return d.object();
}

QList<QByteArray> lines(const QByteArray& out)
{
    QList<QByteArray> result = out.split('\n');
    if (!result.isEmpty() && result.last().isEmpty()) result.removeLast();
    return result;
}

const QStringList kGrid{QStringLiteral("sweep"), kCut, QStringLiteral("--vary"), QStringLiteral("shot.heading=-1.5:1.5:7"),
                        QStringLiteral("--vary"), QStringLiteral("shot.side=-0.3:0.3:4"), QStringLiteral("--goal"),
                        QStringLiteral("pot:1@pocket-tr")};

}  // namespace

class TestSweepCli : public QObject {
    Q_OBJECT

private slots:
    void sweepLineShape();
    void sweepLinesEqualSimulateSet();
    void oneThreadEqualsAll();
    void shardsConcatenateToTheWhole();
    void usageErrorsNameTheCulprit_data();
    void usageErrorsNameTheCulprit();
    void illegalCombinationIsRefusedAndSweepGoesOn();
    void setOnEverySubcommand();
    void setRefusalIsExitOne();
    void standardInput();
};

void TestSweepCli::sweepLineShape()
{
    const Run r = cli(kGrid);
    QCOMPARE(r.status, 0);
    QVERIFY2(r.err.isEmpty(), r.err.constData());
    const QList<QByteArray> all = lines(r.out);
    QCOMPARE(all.size(), 28);
    int met = 0;
    for (int i = 0; i < all.size(); ++i) {
        const QJsonObject o = object(all[i]);
        QCOMPARE(o.value("index").toInt(-1), i);
        const QJsonObject set = o.value("set").toObject();
        QCOMPARE(set.keys(), (QStringList{"shot.heading", "shot.side"}));
        // The last --vary varies fastest.
        QVERIFY(std::abs(set.value("shot.side").toDouble() - (-0.3 + 0.2 * (i % 4))) < 1e-15);
        QVERIFY(std::abs(set.value("shot.heading").toDouble() - (-1.5 + 0.5 * (i / 4))) < 1e-15);
        QVERIFY(o.value("events").toInt() > 0);
        QVERIFY(o.value("end_time").toDouble() > 0);
        const QJsonObject outcome = o.value("outcome").toObject();
        for (const char* key : {"struck_ball", "first_contact", "pocketed", "cushion_hits",
                                "cushions_before_first_contact", "struck_ball_pocketed"})
            QVERIFY2(outcome.contains(QLatin1String(key)), key);
        met += o.value("goal").toBool() ? 1 : 0;
    }
    QVERIFY(met > 0 && met < all.size());
    // Without --goal the lines have exactly the contract's keys.
    const Run plain = cli({"sweep", kCut, "--vary", "shot.speed=1:2:2"});
    QCOMPARE(object(lines(plain.out).first()).keys(), (QStringList{"end_time", "events", "index", "outcome", "set"}));
}

void TestSweepCli::sweepLinesEqualSimulateSet()
{
    const QList<QByteArray> all = lines(cli(kGrid).out);
    for (int i : {0, 5, 13, 27}) {
        const QJsonObject line = object(all[i]);
        const QJsonObject set = line.value("set").toObject();
        // The values as printed (round-trip digits) give back the same doubles.
        QStringList arguments{"simulate", kCut};
        for (const QString& key : set.keys())
            arguments << "--set" << key + '=' + QString::number(set.value(key).toDouble(), 'g', 17);
        const Run single = cli(arguments);
        QCOMPARE(single.status, 0);
        const QJsonObject sim = object(single.out);
        QCOMPARE(line.value("events").toInt(), sim.value("events").toArray().size());
        QCOMPARE(line.value("end_time").toDouble(), sim.value("end_time").toDouble());
        QCOMPARE(line.value("outcome").toObject(), sim.value("outcome").toObject());
    }
}

void TestSweepCli::oneThreadEqualsAll()
{
    const Run all = cli(kGrid);
    const Run one = cli(QStringList(kGrid) << "--jobs" << "1");
    const Run three = cli(QStringList(kGrid) << "--jobs" << "3");
    QCOMPARE(one.status, 0);
    QCOMPARE(one.out, all.out);
    QCOMPARE(three.out, all.out);
}

void TestSweepCli::shardsConcatenateToTheWhole()
{
    const QList<QByteArray> whole = lines(cli(kGrid).out);
    for (int n : {2, 3, 5}) {
        std::map<int, QByteArray> byIndex;
        int total = 0;
        for (int k = 1; k <= n; ++k) {
            const Run shard = cli(QStringList(kGrid) << "--shard" << QStringLiteral("%1/%2").arg(k).arg(n));
            QCOMPARE(shard.status, 0);
            for (const QByteArray& line : lines(shard.out)) {
                const int index = object(line).value("index").toInt();
                QCOMPARE(index % n, k - 1);
                byIndex[index] = line;
                ++total;
            }
        }
        QCOMPARE(total, whole.size());
        QList<QByteArray> merged;
        for (const auto& [index, line] : byIndex) merged << line;
        QCOMPARE(merged, whole);
    }
}

void TestSweepCli::usageErrorsNameTheCulprit_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("named");
    const QString cut = kCut;
    QTest::newRow("unknown key") << QStringList{"sweep", cut, "--vary", "shot.sped=0:1:3"} << "\"shot.sped\"";
    QTest::newRow("count 0") << QStringList{"sweep", cut, "--vary", "shot.speed=1:2:0"} << "COUNT must be at least 1";
    QTest::newRow("count text") << QStringList{"sweep", cut, "--vary", "shot.speed=1:2:x"} << "COUNT is not a whole number";
    QTest::newRow("from text") << QStringList{"sweep", cut, "--vary", "shot.speed=a:2:3"} << "FROM is not a number";
    QTest::newRow("text key") << QStringList{"sweep", cut, "--vary", "table.kind=1:2:3"} << "table.kind: not a number";
    QTest::newRow("no vary") << QStringList{"sweep", cut} << "--vary";
    QTest::newRow("shard 0/3") << QStringList{"sweep", cut, "--vary", "shot.speed=1:2:3", "--shard", "0/3"} << "'0/3'";
    QTest::newRow("shard 4/3") << QStringList{"sweep", cut, "--vary", "shot.speed=1:2:3", "--shard", "4/3"} << "'4/3'";
    QTest::newRow("shard text") << QStringList{"sweep", cut, "--vary", "shot.speed=1:2:3", "--shard", "a"} << "--shard";
    QTest::newRow("jobs 0") << QStringList{"sweep", cut, "--vary", "shot.speed=1:2:3", "--jobs", "0"} << "--jobs";
    QTest::newRow("goal ball") << QStringList{"sweep", cut, "--vary", "shot.speed=1:2:3", "--goal", "pot:9"} << "no ball \"9\"";
    QTest::newRow("goal pocket") << QStringList{"sweep", cut, "--vary", "shot.speed=1:2:3", "--goal", "pot:1@pocket-x"}
                                 << "no pocket \"pocket-x\"";
    QTest::newRow("goal syntax") << QStringList{"sweep", cut, "--vary", "shot.speed=1:2:3", "--goal", "sink:1"} << "\"sink\"";
    QTest::newRow("set unknown key") << QStringList{"simulate", cut, "--set", "shot.sped=3"} << "\"shot.sped\"";
    QTest::newRow("set unknown ball") << QStringList{"validate", cut, "--set", "balls.7.x=1"} << "no ball \"7\"";
    QTest::newRow("set wrong type") << QStringList{"state", cut, "--at", "1", "--set", "shot.speed=fast"}
                                    << "shot.speed: expected a finite number, found \"fast\"";
    QTest::newRow("set bool") << QStringList{"simulate", cut, "--set", "table.pockets=1"} << "table.pockets";
    QTest::newRow("set no =") << QStringList{"trajectory", cut, "--set", "shot.speed"} << "expected KEY=VALUE";
    QTest::newRow("sweep set") << QStringList{"sweep", cut, "--vary", "shot.speed=1:2:3", "--set", "x.y=1"} << "\"x.y\"";
    QTest::newRow("vary elsewhere") << QStringList{"simulate", cut, "--vary", "shot.speed=1:2:3"} << "--vary";
}

void TestSweepCli::usageErrorsNameTheCulprit()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, named);
    const Run r = cli(arguments);
    QCOMPARE(r.status, 2);
    QVERIFY(r.out.isEmpty());
    QVERIFY2(QString::fromUtf8(r.err).contains(named), r.err.constData());
}

void TestSweepCli::illegalCombinationIsRefusedAndSweepGoesOn()
{
    // The 1 sits at x = 1.9338: from x = 1.88 on the cue ball overlaps it.
    const Run r = cli({"sweep", kCut, "--vary", "balls.cue.x=1.7:1.95:6"});
    QCOMPARE(r.status, 0);
    const QList<QByteArray> all = lines(r.out);
    QCOMPARE(all.size(), 6);
    QVERIFY(!object(all[0]).contains("refused"));
    const QJsonObject last = object(all[5]);
    QVERIFY(last.value("outcome").isNull());
    QVERIFY2(last.value("refused").toString().startsWith("half-ball-cut.json: balls[1].position: "),
             qPrintable(last.value("refused").toString()));
    // The same value through --set is refused with the same words (exit 1).
    const Run single = cli({"simulate", kCut, "--set", "balls.cue.x=1.95"});
    QCOMPARE(single.status, 1);
    QCOMPARE(QString::fromUtf8(single.err).trimmed(), "cuelab-cli: " + last.value("refused").toString());
}

void TestSweepCli::setOnEverySubcommand()
{
    const Run validate = cli({"validate", kCut, "--set", "shot.speed=2.5", "--set", "table.kind=pool-8ft"});
    QCOMPARE(validate.status, 0);
    const Run plain = cli({"simulate", kCut});
    const Run soft = cli({"simulate", kCut, "--set", "shot.speed=0.5"});
    QCOMPARE(soft.status, 0);
    QVERIFY(soft.out != plain.out);
    const Run state = cli({"state", kCut, "--at", "0", "--set", "balls.1.x=2.1"});
    QCOMPARE(state.status, 0);
    QCOMPARE(object(state.out).value("balls").toArray().at(1).toObject().value("position").toArray().at(0).toDouble(), 2.1);
    const Run trajectory = cli({"trajectory", kCut, "--set", "simulation.frame_dt=0.5"});
    QCOMPARE(trajectory.status, 0);
    QVERIFY(trajectory.out.contains("\n0.5,cue,"));
    // The same key given twice: the last wins, as options usually do.
    const Run twice = cli({"simulate", kCut, "--set", "shot.speed=9", "--set", "shot.speed=0.5"});
    QCOMPARE(twice.out, soft.out);
}

void TestSweepCli::setRefusalIsExitOne()
{
    const Run r = cli({"simulate", kCut, "--set", "physics.ball_ball.restitution=1.5"});
    QCOMPARE(r.status, 1);
    QVERIFY(r.out.isEmpty());
    QVERIFY2(r.err.startsWith("cuelab-cli: half-ball-cut.json: physics.ball_ball.restitution: "), r.err.constData());
}

void TestSweepCli::standardInput()
{
    QFile file(kCut);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    const Run fromFile = cli({"simulate", kCut, "--set", "shot.speed=1.5"});
    const Run fromStdin = program({"simulate", "-", "--set", "shot.speed=1.5"}, text);
    QCOMPARE(fromStdin.status, 0);
    QCOMPARE(fromStdin.out, fromFile.out);
    const Run sweep = program({"sweep", "-", "--vary", "shot.speed=1:2:3", "--jobs", "2"}, text);
    QCOMPARE(sweep.status, 0);
    QCOMPARE(sweep.out, cli({"sweep", kCut, "--vary", "shot.speed=1:2:3"}).out);
    const Run refused = program({"validate", "-", "--set", "shot.side=2"}, text);
    QCOMPARE(refused.status, 1);
    QVERIFY2(refused.err.startsWith("cuelab-cli: <stdin>: shot.side: "), refused.err.constData());
    const Run broken = program({"validate", "-"}, QByteArray("{\"format\": "));
    QCOMPARE(broken.status, 1);
    QVERIFY2(broken.err.contains("<stdin>"), broken.err.constData());
}

QTEST_GUILESS_MAIN(TestSweepCli)
#include "tst_sweepcli.moc"
