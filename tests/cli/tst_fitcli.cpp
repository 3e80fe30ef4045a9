// `cuelab-cli fit` and `cuelab-cli calibrate` (CONTRACT.md, Extensions version 2) on a synthetic
// recording written to a temporary folder: the printed fields, the fitted setup written by --out
// and replayed by simulate, the same output for any --jobs, refusals (status 1) and usage errors
// (status 2) naming the culprit.

#include "Cli.h"

#include "RecordingFile.h"
#include "SetupFile.h"
#include "SyntheticRecording.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

namespace {

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

void write(const QString& path, const QByteArray& text)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(text) != text.size()) qFatal("cannot write %s", qPrintable(path));
}

// Without the time-consuming tip starts: these tests check the command, not the fit's reach.
const QStringList kQuick{QStringLiteral("--fit"), QStringLiteral("shot.heading,shot.speed")};

}  // namespace

class TestFitCli : public QObject {
    Q_OBJECT
private:
    QTemporaryDir dir_;
    QString shot_, setup_;

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        shot_ = dir_.filePath(QStringLiteral("shot.json"));
        setup_ = dir_.filePath(QStringLiteral("setup.json"));
        cuelab::Setup truth = cuelab::test::caromShot();
        truth.shot->side = truth.shot->height = 0.0;  // only heading and speed are fitted here
        write(shot_, cuelab::io::serializeRecording(cuelab::test::synthesize(truth)));
        cuelab::Setup start = truth;
        start.shot->headingDeg = 16.5;
        start.shot->speed = 2.8;
        write(setup_, cuelab::io::serializeSetup(start));
    }

    void printsTheFit()
    {
        const Run r = cli(QStringList{QStringLiteral("fit"), shot_, QStringLiteral("--setup"), setup_} + kQuick);
        QCOMPARE(r.status, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        for (const char* key : {"rmse", "per_ball", "fitted", "evaluations", "seconds", "rmse_struck", "rmse_all"})
            QVERIFY2(o.contains(QLatin1String(key)), key);
        const QJsonObject fitted = o.value(QStringLiteral("fitted")).toObject();
        QVERIFY(std::abs(fitted.value(QStringLiteral("shot.heading")).toDouble() - 16.0) < 0.05);
        QVERIFY(std::abs(fitted.value(QStringLiteral("shot.speed")).toDouble() / 3.0 - 1.0) < 0.01);
        QCOMPARE(o.value(QStringLiteral("per_ball")).toObject().keys(), (QStringList{"1", "2", "3"}));
        QVERIFY(o.value(QStringLiteral("rmse")).toDouble() < 0.0085);  // the 5 mm noise: 7.1 mm
        QCOMPARE(o.value(QStringLiteral("struck_ball")).toString(), QStringLiteral("1"));
    }

    void writesTheFittedSetup()
    {
        const QString out = dir_.filePath(QStringLiteral("fitted.json"));
        const Run r = cli(QStringList{QStringLiteral("fit"), shot_, QStringLiteral("--setup"), setup_,
                                      QStringLiteral("--out"), out} + kQuick);
        QCOMPARE(r.status, 0);
        QString error;
        const auto fitted = cuelab::io::loadSetup(out, &error);
        QVERIFY2(fitted, qPrintable(error));
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(fitted->shot->headingDeg, o.value(QStringLiteral("fitted")).toObject().value(QStringLiteral("shot.heading")).toDouble());
    }

    void sameForAnyJobs()
    {
        QJsonObject first;
        for (const char* jobs : {"1", "2"}) {
            const Run r = cli(QStringList{QStringLiteral("fit"), shot_, QStringLiteral("--setup"), setup_,
                                          QStringLiteral("--jobs"), QLatin1String(jobs)} + kQuick);
            QCOMPARE(r.status, 0);
            QJsonObject o = QJsonDocument::fromJson(r.out).object();
            o.remove(QStringLiteral("seconds"));
            if (first.isEmpty())
                first = o;
            else
                QCOMPARE(o, first);
        }
    }

    void madeSetupFindsTheStruckBall()
    {
        // No --setup: the setup comes from the recording (default cloth; the carom cloth by --set).
        const Run r = cli({QStringLiteral("fit"), shot_, QStringLiteral("--fit"), QStringLiteral("shot.heading"),
                           QStringLiteral("--set"), QStringLiteral("physics.mu_roll=0.006"), QStringLiteral("--balls"),
                           QStringLiteral("all")});
        QCOMPARE(r.status, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o.value(QStringLiteral("struck_ball")).toString(), QStringLiteral("1"));
        QCOMPARE(o.value(QStringLiteral("balls")).toString(), QStringLiteral("all"));
    }

    void calibrates()
    {
        const Run r = cli({QStringLiteral("calibrate"), shot_, shot_, QStringLiteral("--calibrate"),
                           QStringLiteral("physics.mu_roll"), QStringLiteral("--fit"), QStringLiteral("shot.speed"),
                           QStringLiteral("--set"), QStringLiteral("physics.mu_slide=0.15"), QStringLiteral("--shard"),
                           QStringLiteral("2/2")});
        QCOMPARE(r.status, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QVERIFY(o.value(QStringLiteral("calibrated")).toObject().contains(QStringLiteral("physics.mu_roll")));
        QCOMPARE(o.value(QStringLiteral("recordings")).toArray().size(), qsizetype(1));  // the second of two
    }

    void refusals_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<int>("status");
        QTest::addColumn<QString>("message");
        QTest::newRow("a missing recording") << QStringList{"fit", "/nonexistent/r.json"} << 1
                                             << QStringLiteral("cuelab-cli: r.json: cannot read the file");
        QTest::newRow("an unknown key") << QStringList{"fit", "SHOT", "--fit", "shot.sped"} << 2
                                        << QStringLiteral("cuelab-cli: --fit: unknown key \"shot.sped\"");
        QTest::newRow("a bad --balls") << QStringList{"fit", "SHOT", "--balls", "some"} << 2
                                       << QStringLiteral("cuelab-cli: --balls: expected all or moved, found 'some'");
        QTest::newRow("calibrate without keys") << QStringList{"calibrate", "SHOT"} << 2
                                                << QStringLiteral("cuelab-cli: calibrate: --calibrate KEYS is required");
        QTest::newRow("fit takes one recording") << QStringList{"fit", "SHOT", "SHOT"} << 2
                                                 << QStringLiteral("cuelab-cli: fit: unexpected argument");
        QTest::newRow("no recording") << QStringList{"fit"} << 2 << QStringLiteral("cuelab-cli: fit: no recording given");
    }

    void refusals()
    {
        QFETCH(QStringList, arguments);
        QFETCH(int, status);
        QFETCH(QString, message);
        arguments.replaceInStrings(QStringLiteral("SHOT"), shot_);
        const Run r = cli(arguments);
        QCOMPARE(r.status, status);
        QVERIFY2(r.err.startsWith(message.toUtf8()), r.err.constData());
        QVERIFY(r.out.isEmpty());
    }

    void refusesASetupWithoutARecordedBall()
    {
        cuelab::Setup s = cuelab::test::caromShot();
        s.balls.pop_back();
        const QString path = dir_.filePath(QStringLiteral("two.json"));
        write(path, cuelab::io::serializeSetup(s));
        const Run r = cli({QStringLiteral("fit"), shot_, QStringLiteral("--setup"), path});
        QCOMPARE(r.status, 1);
        QVERIFY2(r.err.startsWith("cuelab-cli: two.json: has no ball \"3\" of shot.json"), r.err.constData());
    }
};

QTEST_GUILESS_MAIN(TestFitCli)
#include "tst_fitcli.moc"
