// `cuelab-cli explain SETUP --event N [--format json|markdown]` (CONTRACT.md, "Extensions"): the
// JSON shape, agreement with `simulate`'s events, no `toi` for a transition, usage errors naming
// the valid range, Markdown for people.

#include "Cli.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <cmath>

namespace {

const QString kExamples = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/");

struct Run {
    int status = -1;
    QByteArray out, err;
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
    if (error.error != QJsonParseError::NoError || !d.isObject()) qFatal("not JSON: %s", qPrintable(error.errorString()));
    return d.object();
}

QJsonArray events(const QString& file)
{
    const Run r = cli({QStringLiteral("simulate"), file});
    if (r.status != 0) qFatal("simulate failed");
    return object(r.out).value(QStringLiteral("events")).toArray();
}

bool allNumbers(const QJsonValue& v)
{
    if (!v.isObject()) return false;
    for (const QJsonValue& x : v.toObject())
        if (!x.isDouble()) return false;
    return true;
}

}  // namespace

class TestExplainCli : public QObject {
    Q_OBJECT
private slots:
    void shapeOfEveryEvent_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("half-ball-cut") << kExamples + "half-ball-cut.json";
        QTest::newRow("one-cushion-bank") << kExamples + "one-cushion-bank.json";
        QTest::newRow("three-cushion") << kExamples + "three-cushion.json";
    }
    void shapeOfEveryEvent()
    {
        QFETCH(QString, file);
        const QJsonArray log = events(file);
        QVERIFY(log.size() > 2);
        for (int i = 0; i < log.size(); ++i) {
            const Run r = cli({QStringLiteral("explain"), file, QStringLiteral("--event"), QString::number(i)});
            QCOMPARE(r.status, 0);
            QVERIFY(r.err.isEmpty());
            const QJsonObject e = object(r.out);
            const QJsonObject simulated = log.at(i).toObject();
            QCOMPARE(e.value("event").toInt(), i);
            QCOMPARE(e.value("type").toString(), simulated.value("type").toString());
            QCOMPARE(e.value("time").toDouble(), simulated.value("time").toDouble());
            const QJsonArray steps = e.value("steps").toArray();
            QVERIFY(!steps.isEmpty());
            for (const QJsonValue& v : steps) {
                const QJsonObject s = v.toObject();
                QVERIFY(s.value("title").isString() && !s.value("title").toString().isEmpty());
                QVERIFY(s.value("formula").isString());
                QVERIFY(allNumbers(s.value("values")));
                QVERIFY(allNumbers(s.value("result")));
            }
            const QString type = simulated.value("type").toString();
            const bool polynomial = type == "ball-ball" || type == "ball-cushion" || type == "ball-pocket";
            QCOMPARE(e.contains("toi"), polynomial);
            if (polynomial) {
                const QJsonObject toi = e.value("toi").toObject();
                const QJsonArray c = toi.value("coefficients").toArray();
                QVERIFY(c.size() >= 1 && c.size() <= 5);
                for (const QJsonValue& x : c) QVERIFY(x.isDouble());
                const double t = toi.value("t0").toDouble() + toi.value("root").toDouble();
                QVERIFY2(std::abs(t - e.value("time").toDouble()) <= 1e-12 * std::max(1.0, t), qPrintable(QString::number(i)));
            }
        }
    }

    void ballBallHasAQuartic()
    {
        const QString file = kExamples + "half-ball-cut.json";
        const QJsonArray log = events(file);
        int hit = -1;
        for (int i = 0; i < log.size() && hit < 0; ++i)
            if (log.at(i).toObject().value("type").toString() == "ball-ball") hit = i;
        QVERIFY(hit >= 0);
        const QJsonObject e = object(cli({"explain", file, "--event", QString::number(hit), "--format", "json"}).out);
        QCOMPARE(e.value("toi").toObject().value("coefficients").toArray().size(), 5);
        QCOMPARE(e.value("balls").toArray().size(), 2);
    }

    // CONTRACT.md version 2: the geometry step's result gains cut_angle (degrees) and ball_fraction.
    // The half-ball cut is set up as its name says: 30° and 0.5 (core/aim, hand-worked in tst_aim); the
    // momentum step gives the centre-of-mass momenta, equal and opposite.
    void aimReadouts()
    {
        const QString file = kExamples + "half-ball-cut.json";
        const Run r = cli({"explain", file, "--event", "#2"});
        QCOMPARE(r.status, 0);
        const QJsonObject e = object(r.out);
        QJsonObject geometry, momentum;
        for (const QJsonValue& s : e.value("steps").toArray()) {
            if (s.toObject().value("title").toString() == "Contact geometry") geometry = s.toObject().value("result").toObject();
            if (s.toObject().value("title").toString() == "Momentum before and after") momentum = s.toObject().value("result").toObject();
        }
        QVERIFY(geometry.value("cut_angle").isDouble());
        QVERIFY(std::abs(geometry.value("cut_angle").toDouble() - 30.0) < 1e-3);
        QVERIFY(std::abs(geometry.value("ball_fraction").toDouble() - 0.5) < 1e-3);
        for (const char* axis : {"_x", "_y"}) {
            const double a = momentum.value(QStringLiteral("p_cm_a") + axis).toDouble();
            const double b = momentum.value(QStringLiteral("p_cm_b") + axis).toDouble();
            QVERIFY(momentum.contains(QStringLiteral("p_cm_a") + axis));
            QVERIFY(std::abs(a + b) < 1e-12);
        }
        QVERIFY(std::abs(momentum.value("p_cm_a_x").toDouble()) > 0.01);
        const Run md = cli({"explain", file, "--event", "#2", "--format", "markdown"});
        QCOMPARE(md.status, 0);
        QVERIFY(md.out.contains("ball fraction"));
        QVERIFY(md.out.contains("centre of mass"));
        // The transition after it has no aiming geometry.
        const QJsonObject t = object(cli({"explain", file, "--event", "#3"}).out);
        QVERIFY(!QJsonDocument(t).toJson().contains("cut_angle"));
    }

    void markdown()
    {
        const Run r = cli({"explain", kExamples + "half-ball-cut.json", "--event", "0", "--format", "markdown"});
        QCOMPARE(r.status, 0);
        QVERIFY(r.out.startsWith("## Cue strike"));
        QVERIFY(r.out.contains("Alciatore"));
    }

    void usageErrors_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("message");
        const QString f = kExamples + "straight-shot.json";
        QTest::newRow("out of range") << QStringList{"explain", f, "--event", "9999"} << "give 0 to ";
        QTest::newRow("negative") << QStringList{"explain", f, "--event", "-1"} << "--event: expected a whole number >= 0";
        QTest::newRow("not a number") << QStringList{"explain", f, "--event", "two"} << "--event: expected a whole number >= 0";
        QTest::newRow("fraction") << QStringList{"explain", f, "--event", "1.5"} << "--event: expected a whole number >= 0";
        QTest::newRow("missing") << QStringList{"explain", f} << "--event N is required";
        QTest::newRow("format") << QStringList{"explain", f, "--event", "0", "--format", "xml"} << "json or markdown";
    }
    void usageErrors()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        const Run r = cli(arguments);
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.contains(message.toUtf8()), r.err.constData());
        QVERIFY(r.out.isEmpty());
    }

    void refusedSetup()
    {
        const Run r = cli({"explain", QStringLiteral(CUELAB_SOURCE_DIR "/does-not-exist.json"), "--event", "0"});
        QCOMPARE(r.status, 1);
    }
};

QTEST_GUILESS_MAIN(TestExplainCli)
#include "tst_explaincli.moc"
