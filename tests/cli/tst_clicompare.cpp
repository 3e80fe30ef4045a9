// `cuelab-cli compare` (CONTRACT.md, Extensions): the output's shape for each engine, usage errors
// naming the option, byte-identical repeated runs.

#include "Cli.h"
#include "ExamplePath.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using namespace cuelab;

namespace {

struct Result {
    int status = -1;
    QByteArray out, err;
};

Result run(const QStringList& args)
{
    Result r;
    r.status = cli::run(QStringList{QStringLiteral("cuelab-cli"), QStringLiteral("compare")} + args, &r.out, &r.err);
    return r;
}

QString example(const char* name) { return examplePath(name); }

}  // namespace

class TestCliCompare : public QObject {
    Q_OBJECT
private slots:
    void outputShape_data();
    void outputShape();
    void exactIgnoresNoOptionSilently();
    void fastGrazeAtSixtyHertzAndAtOneMillisecond();
    void usageErrors_data();
    void usageErrors();
    void refusedSetup();
    void identicalRuns();
};

void TestCliCompare::outputShape_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("engine");
    QTest::newRow("exact") << QStringList{"--engine", "exact"} << "exact";
    QTest::newRow("discrete default") << QStringList{"--engine", "discrete"} << "discrete";
    QTest::newRow("discrete 1 ms") << QStringList{"--engine", "discrete", "--dt", "0.001", "--substeps", "4"} << "discrete";
    QTest::newRow("box2d") << QStringList{"--engine", "box2d", "--dt", "0.005", "--substeps", "12"} << "box2d";
}

void TestCliCompare::outputShape()
{
    QFETCH(QStringList, args);
    QFETCH(QString, engine);
    const Result r = run(QStringList{example("half-ball-cut.json")} + args);
    QVERIFY2(r.status == 0, r.err.constData());
    QJsonParseError error;
    const QJsonObject o = QJsonDocument::fromJson(r.out, &error).object();
    QCOMPARE(error.error, QJsonParseError::NoError);
    QCOMPARE(o.value("engine").toString(), engine);
    if (engine == "exact") {
        QVERIFY(o.value("dt").isNull());
        QVERIFY(o.value("substeps").isNull());
    } else {
        QVERIFY(o.value("dt").toDouble() > 0.0);
        QVERIFY(o.value("substeps").toInt() >= 1);
        if (args.contains("--dt")) QCOMPARE(o.value("dt").toDouble(), args[args.indexOf("--dt") + 1].toDouble());
        if (args.contains("--substeps")) QCOMPARE(o.value("substeps").toInt(), args[args.indexOf("--substeps") + 1].toInt());
    }
    const QJsonArray events = o.value("events").toArray();
    QVERIFY(!events.isEmpty());
    double previous = 0.0;
    for (const QJsonValue& v : events) {
        const QJsonObject e = v.toObject();
        QVERIFY(e.value("time").toDouble() >= previous);
        previous = e.value("time").toDouble();
        const QString type = e.value("type").toString();
        QVERIFY(type == "ball-ball" || type == "ball-cushion" || type == "ball-pocket");
        QCOMPARE(e.value("balls").toArray().size(), type == "ball-ball" ? 2 : 1);
    }
    const QJsonArray balls = o.value("balls").toArray();
    QCOMPARE(balls.size(), 2);
    QCOMPARE(balls[0].toObject().value("id").toString(), QStringLiteral("cue"));
    QVERIFY(!balls[0].toObject().value("state").toString().isEmpty());
    QCOMPARE(balls[0].toObject().value("position").toArray().size(), 2);
    const QJsonObject d = o.value("divergence").toObject();
    QVERIFY(d.value("max_position_error").isDouble());
    const QJsonObject finals = d.value("final_position_error").toObject();
    QCOMPARE(finals.keys(), (QStringList{"1", "cue"}));
    QVERIFY(d.value("first_sequence_difference").isNull() || d.value("first_sequence_difference").isDouble());
    QVERIFY(d.value("worst_overlap").toDouble() >= 0.0);
    if (engine == "exact") {
        QCOMPARE(d.value("max_position_error").toDouble(), 0.0);
        QVERIFY(d.value("first_sequence_difference").isNull());
        QVERIFY(o.value("warnings").toArray().isEmpty());
    } else {
        QVERIFY(d.value("max_position_error").toDouble() > 0.0);
        QVERIFY(!o.value("warnings").toArray().isEmpty());  // no slide phase, mirror cushions
    }
}

void TestCliCompare::exactIgnoresNoOptionSilently()
{
    const Result r = run({example("half-ball-cut.json"), "--engine", "exact", "--dt", "0.01"});
    QCOMPARE(r.status, 0);
    const QJsonArray warnings = QJsonDocument::fromJson(r.out).object().value("warnings").toArray();
    QCOMPARE(warnings.size(), 1);
    QVERIFY(warnings[0].toString().startsWith("--dt does not apply to the exact engine"));
}

void TestCliCompare::fastGrazeAtSixtyHertzAndAtOneMillisecond()
{
    const Result coarse = run({example("fast-graze.json"), "--engine", "discrete", "--dt", "0.0166666666666667"});
    QCOMPARE(coarse.status, 0);
    const QJsonObject c = QJsonDocument::fromJson(coarse.out).object();
    QCOMPARE(c.value("events").toArray()[0].toObject().value("type").toString(), QStringLiteral("ball-cushion"));
    QCOMPARE(c.value("divergence").toObject().value("first_sequence_difference").toInt(-1), 0);
    const Result fine = run({example("fast-graze.json"), "--engine", "discrete", "--dt", "0.001"});
    const QJsonObject f = QJsonDocument::fromJson(fine.out).object();
    QCOMPARE(f.value("events").toArray()[0].toObject().value("type").toString(), QStringLiteral("ball-ball"));
    QCOMPARE(f.value("balls").toArray()[1].toObject().value("pocket").toString(), QStringLiteral("pocket-t"));
}

void TestCliCompare::usageErrors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("named");
    QTest::newRow("no engine") << QStringList{} << "--engine";
    QTest::newRow("unknown engine") << QStringList{"--engine", "bullet"} << "--engine: unknown engine 'bullet'";
    QTest::newRow("zero step") << QStringList{"--engine", "discrete", "--dt", "0"} << "--dt: expected a number of seconds > 0";
    QTest::newRow("negative step") << QStringList{"--engine", "box2d", "--dt", "-0.01"} << "--dt";
    QTest::newRow("not a number") << QStringList{"--engine", "discrete", "--dt", "fast"} << "--dt";
    QTest::newRow("discrete step too small") << QStringList{"--engine", "discrete", "--dt", "1e-7"}
                                             << "--dt: 1e-07 s is below the smallest discrete step, 1e-05 s";
    QTest::newRow("box2d step too small") << QStringList{"--engine", "box2d", "--dt", "1e-5"}
                                          << "--dt: 1e-05 s is below the smallest box2d step, 1e-04 s: Box2D computes in 32-bit floats";
    QTest::newRow("step too large") << QStringList{"--engine", "discrete", "--dt", "5"} << "--dt: 5 s is above";
    QTest::newRow("zero substeps") << QStringList{"--engine", "discrete", "--substeps", "0"} << "--substeps: expected a whole number >= 1";
    QTest::newRow("fractional substeps") << QStringList{"--engine", "box2d", "--substeps", "2.5"} << "--substeps";
    QTest::newRow("too many substeps") << QStringList{"--engine", "discrete", "--substeps", "100000"} << "--substeps";
    QTest::newRow("max-events") << QStringList{"--engine", "exact", "--max-events", "5"} << "max-events";
}

void TestCliCompare::usageErrors()
{
    QFETCH(QStringList, args);
    QFETCH(QString, named);
    const Result r = run(QStringList{example("half-ball-cut.json")} + args);
    QCOMPARE(r.status, 2);
    QVERIFY(r.out.isEmpty());
    QVERIFY2(QString::fromUtf8(r.err).contains(named), r.err.constData());
}

void TestCliCompare::refusedSetup()
{
    const Result r = run({QStringLiteral(CUELAB_SOURCE_DIR "/does-not-exist.json"), "--engine", "discrete"});
    QCOMPARE(r.status, 1);
    QVERIFY(r.err.contains("does-not-exist.json"));
}

void TestCliCompare::identicalRuns()
{
    const QStringList args{example("9-ball-break.json"), "--engine", "box2d"};
    const Result a = run(args), b = run(args);
    QCOMPARE(a.status, 0);
    QCOMPARE(a.out, b.out);
}

QTEST_GUILESS_MAIN(TestCliCompare)
#include "tst_clicompare.moc"
