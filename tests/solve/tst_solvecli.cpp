// `cuelab-cli solve` (CONTRACT.md, Extensions version 3): the printed fields, every probability
// equal to what `odds --set ... --seed S` says for that strike, the same bytes for any --jobs (the
// wall time aside), an empty list when nothing meets the goal, and bad input as a usage error
// (exit 2) naming the culprit.

#include "Cli.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTest>

namespace {

const QString kStraight = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/straight-shot.json");

struct Run {
    int status = -1;
    QByteArray out;
    QByteArray err;
};

Run cli(QStringList arguments)
{
    arguments.prepend(QStringLiteral("cuelab-cli"));
    Run r;
    r.status = cuelab::cli::run(arguments, &r.out, &r.err);
    return r;
}

QJsonObject object(const QByteArray& text)
{
    QJsonParseError error;
    const QJsonDocument d = QJsonDocument::fromJson(text, &error);
    if (error.error != QJsonParseError::NoError || !d.isObject()) qFatal("not JSON: %s", text.constData());
    return d.object();
}

const QStringList kSolve = {"solve", kStraight, "--goal", "pot:1@pocket-tr,no-scratch", "--samples", "200",
                            "--seed", "3", "--top", "2"};

}  // namespace

class TestSolveCli : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void printsTheContractsFields();
    void probabilityIsWhatOddsSays();
    void sameForAnyJobs();
    void noShotMeetsTheGoal();
    void usageErrorsNameTheCulprit_data();
    void usageErrorsNameTheCulprit();

private:
    Run solved_;
};

void TestSolveCli::initTestCase()
{
    solved_ = cli(kSolve + QStringList{"--jobs", "2"});
    QCOMPARE(solved_.status, 0);
    QVERIFY2(solved_.err.isEmpty(), solved_.err.constData());
}

void TestSolveCli::printsTheContractsFields()
{
    const QJsonObject o = object(solved_.out);
    QCOMPARE(o.value("goal").toString(), QStringLiteral("pot:1@pocket-tr,no-scratch"));
    // The default noise is the club preset: 0.3°, 0.12 m/s, 1.5 mm of tip (in radii), 0.3°.
    const QJsonObject noise = o.value("noise").toObject();
    QCOMPARE(noise.size(), 5);
    QCOMPARE(noise.value("shot.heading").toDouble(), 0.3);
    QCOMPARE(noise.value("shot.speed").toDouble(), 0.12);
    QVERIFY(std::abs(noise.value("shot.side").toDouble() - 0.0015 / 0.028575) < 1e-15);
    QVERIFY(o.value("evaluations").toInteger() > 1000);
    QVERIFY(o.value("seconds").toDouble() > 0.0);
    const QJsonArray shots = o.value("shots").toArray();
    QVERIFY(!shots.isEmpty() && shots.size() <= 2);
    const QStringList routes = {"direct", "kick", "combination", "jump", "masse"};
    double previous = 1.0;
    for (qsizetype i = 0; i < shots.size(); ++i) {
        const QJsonObject shot = shots[i].toObject();
        QCOMPARE(shot.value("rank").toInt(), static_cast<int>(i) + 1);
        const QJsonObject set = shot.value("set").toObject();
        QCOMPARE(set.keys(), (QStringList{"shot.heading", "shot.height", "shot.side", "shot.speed"}));
        const double p = shot.value("probability").toDouble();
        QVERIFY(p > 0.0 && p <= previous);
        previous = p;
        const QJsonArray ci = shot.value("ci95").toArray();
        QCOMPARE(ci.size(), 2);
        QVERIFY(ci[0].toDouble() <= p && p <= ci[1].toDouble());
        QCOMPARE(shot.value("samples").toInteger(), 200);
        const QString route = shot.value("route").toString();
        QVERIFY2(routes.contains(route) || QRegularExpression("^bank \\d+ cushions$").match(route).hasMatch(),
                 qPrintable(route));
        QVERIFY(shot.value("first_contact").isString());
        const QJsonObject tolerance = shot.value("tolerance").toObject();
        QCOMPARE(tolerance.keys(), set.keys());
        for (const QString& key : tolerance.keys()) {
            const QJsonValue w = tolerance.value(key);
            QVERIFY(w.isNull() || (w.isArray() && w.toArray().size() == 2 && w.toArray()[0].toDouble() <= w.toArray()[1].toDouble()));
        }
    }
    QCOMPARE(shots[0].toObject().value("route").toString(), QStringLiteral("direct"));
    QCOMPARE(shots[0].toObject().value("first_contact").toString(), QStringLiteral("1"));
}

void TestSolveCli::probabilityIsWhatOddsSays()
{
    const QJsonArray shots = object(solved_.out).value("shots").toArray();
    for (const QJsonValue& value : shots) {
        const QJsonObject shot = value.toObject();
        QStringList arguments = {"odds", kStraight, "--goal", "pot:1@pocket-tr,no-scratch", "--noise", "club",
                                 "--samples", "200", "--seed", "3"};
        const QJsonObject set = shot.value("set").toObject();
        for (const QString& key : set.keys())
            arguments << "--set" << key + "=" + QString::number(set.value(key).toDouble(), 'g', 17);
        const Run odds = cli(arguments);
        QCOMPARE(odds.status, 0);
        const QJsonObject o = object(odds.out);
        QCOMPARE(o.value("probability").toDouble(), shot.value("probability").toDouble());
        QCOMPARE(o.value("ci95").toArray(), shot.value("ci95").toArray());
        QCOMPARE(o.value("samples").toInteger(), shot.value("samples").toInteger());
    }
}

void TestSolveCli::sameForAnyJobs()
{
    const Run one = cli(kSolve + QStringList{"--jobs", "1"});
    QCOMPARE(one.status, 0);
    QJsonObject a = object(one.out), b = object(solved_.out);
    a.remove("seconds");
    b.remove("seconds");
    QCOMPARE(a, b);
}

void TestSolveCli::noShotMeetsTheGoal()
{
    const Run r = cli({"solve", kStraight, "--goal", "pot:1,!pot:1", "--samples", "50"});
    QCOMPARE(r.status, 0);
    QVERIFY(object(r.out).value("shots").toArray().isEmpty());
}

void TestSolveCli::usageErrorsNameTheCulprit_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("named");
    QTest::newRow("no goal") << QStringList{} << "--goal";
    QTest::newRow("missing ball") << QStringList{"--goal", "pot:9"} << "\"9\"";
    QTest::newRow("missing pocket") << QStringList{"--goal", "pot:1@pocket-x"} << "pocket-x";
    QTest::newRow("zone off the table") << QStringList{"--goal", "pot:1,in:cue@3:2:4:3"} << "off the table";
    QTest::newRow("bad goal") << QStringList{"--goal", "sink:1"} << "sink";
    QTest::newRow("noise key") << QStringList{"--goal", "pot:1", "--noise", "shot.sped=1"} << "shot.sped";
    QTest::newRow("noise preset") << QStringList{"--goal", "pot:1", "--noise", "amateur"} << "amateur";
    QTest::newRow("vary key") << QStringList{"--goal", "pot:1", "--vary", "shot.heading,physics.mu_roll"}
                              << "physics.mu_roll";
    QTest::newRow("top") << QStringList{"--goal", "pot:1", "--top", "0"} << "--top";
}

void TestSolveCli::usageErrorsNameTheCulprit()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, named);
    const Run r = cli(QStringList{"solve", kStraight} + arguments);
    QCOMPARE(r.status, 2);
    QVERIFY(r.out.isEmpty());
    QVERIFY2(QString::fromUtf8(r.err).contains(named), r.err.constData());
}

QTEST_GUILESS_MAIN(TestSolveCli)
#include "tst_solvecli.moc"
