// `cuelab-cli odds` and `sweep --noise` (CONTRACT.md, version 2, "odds"): the printed fields, one
// thread and all print identical bytes, a grid point's odds equal `odds --set` of that point, and
// bad input is a usage error (exit 2) naming the culprit.

#include "Cli.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
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

QList<QByteArray> lines(const QByteArray& out)
{
    QList<QByteArray> result = out.split('\n');
    if (!result.isEmpty() && result.last().isEmpty()) result.removeLast();
    return result;
}

}  // namespace

class TestOddsCli : public QObject {
    Q_OBJECT

private slots:
    void oddsPrintsTheContractsFields();
    void identicalForAnyJobs();
    void sweepLinesCarryOdds();
    void usageErrorsNameTheCulprit_data();
    void usageErrorsNameTheCulprit();
};

void TestOddsCli::oddsPrintsTheContractsFields()
{
    const Run r = cli({"odds", kStraight, "--goal", "pot:1@pocket-tr", "--noise", "shot.heading=0.0001", "--samples",
                       "300", "--seed", "5"});
    QCOMPARE(r.status, 0);
    QVERIFY2(r.err.isEmpty(), r.err.constData());
    QCOMPARE(lines(r.out).size(), 1);
    const QJsonObject o = object(r.out);
    // A ten-thousandth of a degree never misses the straight pot: 300 of 300.
    QCOMPARE(o.value("probability").toDouble(), 1.0);
    QCOMPARE(o.value("samples").toInteger(), 300);
    QCOMPARE(o.value("successes").toInteger(), 300);
    const QJsonArray ci = o.value("ci95").toArray();
    QCOMPARE(ci.size(), 2);
    // Wilson at 300 of 300: low = n / (n + z²) = 300 / 303.841459 = 0.987357.
    QVERIFY(std::abs(ci[0].toDouble() - 0.987357) < 1e-6);
    QVERIFY(std::abs(ci[1].toDouble() - 1.0) < 1e-12);
    QCOMPARE(o.value("noise").toObject().value("shot.heading").toDouble(), 0.0001);
    QCOMPARE(o.value("stopped_early").toBool(), false);
    // --half-width stops at a batch boundary: 250 samples already give 1.882 / 250 < 0.01.
    const Run early = cli({"odds", kStraight, "--goal", "pot:1@pocket-tr", "--noise", "shot.heading=0.0001", "--samples",
                           "1000", "--half-width", "0.01"});
    QCOMPARE(early.status, 0);
    QCOMPARE(object(early.out).value("samples").toInteger(), 250);
    QCOMPARE(object(early.out).value("stopped_early").toBool(), true);
}

void TestOddsCli::identicalForAnyJobs()
{
    const QStringList base{"odds", kStraight, "--goal", "pot:1@pocket-tr,no-scratch", "--noise", "club", "--noise",
                           "shot.speed=0.2", "--samples", "600", "--seed", "99"};
    const Run one = cli(base + QStringList{"--jobs", "1"});
    const Run all = cli(base);
    const Run three = cli(base + QStringList{"--jobs", "3"});
    QCOMPARE(one.status, 0);
    QCOMPARE(one.out, all.out);
    QCOMPARE(one.out, three.out);
    const QJsonObject o = object(one.out);
    QVERIFY(o.value("successes").toInteger() > 0 && o.value("successes").toInteger() < 600);  // a club player misses some
    // The preset then the key: the key overrides the preset's speed.
    QCOMPARE(o.value("noise").toObject().value("shot.speed").toDouble(), 0.2);
    QCOMPARE(o.value("noise").toObject().value("shot.heading").toDouble(), 0.3);
    // Another seed draws other errors.
    const Run other = cli({"odds", kStraight, "--goal", "pot:1@pocket-tr,no-scratch", "--noise", "club", "--noise",
                           "shot.speed=0.2", "--samples", "600", "--seed", "100"});
    QVERIFY(other.out != one.out);
}

void TestOddsCli::sweepLinesCarryOdds()
{
    const QStringList sweep{"sweep", kStraight, "--vary", "shot.heading=39.5:40.5:3", "--goal", "pot:1@pocket-tr",
                            "--noise", "shot.heading=0.2", "--samples", "200"};
    const Run one = cli(sweep + QStringList{"--jobs", "1"});
    const Run all = cli(sweep);
    QCOMPARE(one.status, 0);
    QCOMPARE(one.out, all.out);
    const QList<QByteArray> rows = lines(one.out);
    QCOMPARE(rows.size(), 3);
    for (const QByteArray& row : rows) {
        const QJsonObject o = object(row);
        QVERIFY(o.contains("goal"));
        QCOMPARE(o.value("samples").toInteger(), 200);
        QCOMPARE(o.value("ci95").toArray().size(), 2);
    }
    // The middle point's odds are `odds --set` of its value.
    const Run single = cli({"odds", kStraight, "--set", "shot.heading=40", "--goal", "pot:1@pocket-tr", "--noise",
                            "shot.heading=0.2", "--samples", "200"});
    const QJsonObject middle = object(rows[1]);
    QCOMPARE(middle.value("successes"), object(single.out).value("successes"));
    QCOMPARE(middle.value("ci95"), object(single.out).value("ci95"));
}

void TestOddsCli::usageErrorsNameTheCulprit_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("named");
    const QString s = kStraight;
    const QStringList odds{"odds", s, "--goal", "pot:1"};
    QTest::newRow("not a strike key") << odds + QStringList{"--noise", "physics.mu_roll=0.001"}
                                      << "--noise: \"physics.mu_roll\" is not a strike key";
    QTest::newRow("negative sigma") << odds + QStringList{"--noise", "shot.heading=-0.2"}
                                    << "shot.heading: SIGMA must not be negative, found -0.2";
    QTest::newRow("sigma text") << odds + QStringList{"--noise", "shot.speed=lots"} << "shot.speed: SIGMA is not a number";
    QTest::newRow("unknown preset") << odds + QStringList{"--noise", "beginner"} << "\"beginner\"";
    QTest::newRow("zero samples") << odds + QStringList{"--noise", "fastfiz", "--samples", "0"} << "--samples";
    QTest::newRow("samples text") << odds + QStringList{"--noise", "fastfiz", "--samples", "1e4"} << "'1e4'";
    QTest::newRow("negative seed") << odds + QStringList{"--noise", "fastfiz", "--seed", "-1"} << "--seed";
    QTest::newRow("half-width") << odds + QStringList{"--noise", "fastfiz", "--half-width", "2"} << "--half-width";
    QTest::newRow("jobs 0") << odds + QStringList{"--noise", "fastfiz", "--jobs", "0"} << "--jobs";
    QTest::newRow("no noise") << odds << "--noise KEY=SIGMA";
    QTest::newRow("no goal") << QStringList{"odds", s, "--noise", "fastfiz"} << "--goal GOAL is required";
    QTest::newRow("goal ball") << QStringList{"odds", s, "--goal", "pot:9", "--noise", "fastfiz"} << "no ball \"9\"";
    QTest::newRow("sweep noise without goal")
        << QStringList{"sweep", s, "--vary", "shot.speed=1:2:2", "--noise", "fastfiz"} << "--noise needs --goal";
    QTest::newRow("sweep samples without noise")
        << QStringList{"sweep", s, "--vary", "shot.speed=1:2:2", "--goal", "pot:1", "--samples", "10"}
        << "--samples needs --noise";
    QTest::newRow("sweep zero samples")
        << QStringList{"sweep", s, "--vary", "shot.speed=1:2:2", "--goal", "pot:1", "--noise", "shot.speed=0.1",
                       "--samples", "0"}
        << "--samples";
    QTest::newRow("noise elsewhere") << QStringList{"simulate", s, "--noise", "fastfiz"} << "--noise";
}

void TestOddsCli::usageErrorsNameTheCulprit()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, named);
    const Run r = cli(arguments);
    QCOMPARE(r.status, 2);
    QVERIFY(r.out.isEmpty());
    QVERIFY2(QString::fromUtf8(r.err).contains(named), r.err.constData());
}

QTEST_GUILESS_MAIN(TestOddsCli)
#include "tst_oddscli.moc"
