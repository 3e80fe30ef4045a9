// cuelab-cli and CONTRACT.md's "Extensions, version 2" (issue 20): files legal under version 1 load
// again (values beyond real play are warned about by `validate` on stderr, exit 0, and simulate);
// `--set` reaches every key of a full setup file (each set to its own value changes nothing).

#include "Cli.h"

#include "Override.h"
#include "SetupFile.h"

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

// In process, through the same entry point as the program.
Run cli(QStringList arguments)
{
    arguments.prepend(QStringLiteral("cuelab-cli"));
    Run r;
    r.status = cuelab::cli::run(arguments, &r.out, &r.err);
    return r;
}

QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& text)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size()) qFatal("cannot write %s", qPrintable(name));
    return path;
}

QJsonObject object(const QByteArray& text)
{
    QJsonParseError error;
    const QJsonDocument d = QJsonDocument::fromJson(text, &error);
    if (error.error != QJsonParseError::NoError || !d.isObject()) qFatal("not JSON: %s", text.constData());
    return d.object();
}

// A setup file that gives every key of the format (name, notes, every table, physics, ball and shot
// key, end_mass, simulation), with the cushion model `model` and its own parameter `parameter`.
QByteArray fullSetup(const char* model, const char* parameter)
{
    return QByteArray(R"({"format": "cuelab-setup", "version": 1, "name": "Every key", "notes": "a = b, with spaces",
  "table": {"kind": "pool-8ft", "length": 2.3, "width": 1.15, "cushion_height": 0.037, "pockets": true},
  "physics": {"gravity": 9.8, "mu_slide": 0.21, "mu_roll": 0.011, "mu_spin": 0.013,
              "ball_ball": {"model": "frictional", "restitution": 0.94, "friction": 0.06},
              "ball_cushion": {"model": ")") + model + R"(", "restitution": 0.84, "friction": 0.19)" + parameter + R"(}},
  "balls": [{"id": "cue", "position": [0.6, 0.55], "velocity": [0.1, 0.05], "spin": [1, -2, 3], "radius": 0.0286, "mass": 0.171},
            {"id": "1", "position": [1.7, 0.6]}],
  "shot": {"ball": "cue", "speed": 2.5, "heading": 3.5, "elevation": 4, "side": 0.1, "height": 0.2,
           "cue_mass": 0.55, "end_mass": 0.006},
  "simulation": {"frame_dt": 0.02, "max_time": 300}})";
}

}  // namespace

class TestCliContract : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void validateWarnsBeyondRealPlay_data();
    void validateWarnsBeyondRealPlay();
    void setRoundTripsEveryKey_data();
    void setRoundTripsEveryKey();
    void sweepIndexIsAWholeNumber();
};

void TestCliContract::validateWarnsBeyondRealPlay_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QByteArray>("err");  // the whole of stderr
    QTest::newRow("40 m table, 40 m/s ball, 3000 rad/s")
        << QByteArray(R"({"format": "cuelab-setup", "version": 1, "table": {"kind": "carom", "length": 40, "width": 20},
            "balls": [{"id": "a", "position": [1, 10], "velocity": [40, 0], "spin": [0, 3000, 0]}],
            "simulation": {"max_time": 3600}})")
        << QByteArray("cuelab-cli: warning: extreme.json: table.length: 40 m is beyond real play (up to 10 m); it loads and simulates as given\n"
                      "cuelab-cli: warning: extreme.json: table.width: 20 m is beyond real play (up to 10 m); it loads and simulates as given\n"
                      "cuelab-cli: warning: extreme.json: balls[0].velocity: ball \"a\": velocity 40 m/s is beyond real play (up to 20 m/s); it loads and simulates as given\n"
                      "cuelab-cli: warning: extreme.json: balls[0].spin: ball \"a\": spin 3000 rad/s is beyond real play (up to 2000 rad/s); it loads and simulates as given\n");
    QTest::newRow("a 40 m/s shot")
        << QByteArray(R"({"format": "cuelab-setup", "version": 1, "balls": [{"id": "cue", "position": [0.6, 0.6]}],
            "shot": {"ball": "cue", "speed": 40, "heading": 10, "elevation": 0, "side": 0, "height": 0}})")
        << QByteArray("cuelab-cli: warning: extreme.json: shot.speed: 40 m/s is beyond real play (up to 20 m/s); it loads and simulates as given\n");
    QTest::newRow("real play: silent")
        << QByteArray(R"({"format": "cuelab-setup", "version": 1, "balls": [{"id": "cue", "position": [0.6, 0.6], "velocity": [20, 0]}]})")
        << QByteArray();
}

void TestCliContract::validateWarnsBeyondRealPlay()
{
    QFETCH(QByteArray, json);
    QFETCH(QByteArray, err);
    const QString path = writeFile(dir_, QStringLiteral("extreme.json"), json);
    const Run v = cli({"validate", path});
    QCOMPARE(v.status, 0);
    QVERIFY(v.out.isEmpty());
    QCOMPARE(v.err, err);
    // And it simulates to rest; simulate itself does not warn (its output stays as in version 1).
    const Run s = cli({"simulate", path});
    QVERIFY2(s.status == 0, s.err.constData());
    QVERIFY(s.err.isEmpty());
    QVERIFY(object(s.out).value("events").toArray().size() >= 2);
}

void TestCliContract::setRoundTripsEveryKey_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("value");  // the file's own value, as --set takes it
    const QList<QPair<const char*, QByteArray>> files{
        {"mathavan2010", fullSetup("mathavan2010", R"(, "steps": 500)")},
        {"stronge", fullSetup("stronge", R"(, "omega_ratio": 1.7)")},
        {"han2005", fullSetup("han2005", "")},
        {"mirror", fullSetup("mirror", "")},
    };
    for (const auto& [model, json] : files) {
        QString error;
        const std::optional<cuelab::Setup> setup = cuelab::io::parseSetup(json, QStringLiteral("full.json"), &error);
        if (!setup) qFatal("%s", qPrintable(error));
        for (const std::string& key : cuelab::analysis::overridableKeys(*setup, false)) {
            const auto p = std::get<cuelab::analysis::Parameter>(cuelab::analysis::Parameter::resolve(*setup, key));
            QTest::newRow(qPrintable(QStringLiteral("%1: %2").arg(QLatin1String(model), QString::fromStdString(key))))
                << json << QString::fromStdString(key) << QString::fromStdString(p.text(*setup));
        }
    }
}

// Each key set to the file's own value: the same simulation, byte for byte, and the same file when
// saved again (so name and notes, which the simulation does not print, are checked too).
void TestCliContract::setRoundTripsEveryKey()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, key);
    QFETCH(QString, value);
    const QString path = writeFile(dir_, QStringLiteral("full.json"), json);
    const Run plain = cli({"simulate", path});
    QVERIFY2(plain.status == 0, plain.err.constData());
    const Run set = cli({"simulate", path, "--set", key + '=' + value});
    QVERIFY2(set.status == 0, set.err.constData());
    QCOMPARE(set.out, plain.out);

    QString error;
    std::optional<cuelab::Setup> setup = cuelab::io::parseSetup(json, QStringLiteral("full.json"), &error);
    QVERIFY(setup);
    const QByteArray before = cuelab::io::serializeSetup(*setup);
    const auto problem = cuelab::analysis::applyOverride(*setup, key.toStdString(), value.toStdString());
    QVERIFY2(!problem, problem ? problem->message.c_str() : "");
    QCOMPARE(cuelab::io::serializeSetup(*setup), before);
}

// A grid of 100001 shots, of which shard 100001/100001 runs only the last: its index prints as digits
// ("1e+05" before version 2).
void TestCliContract::sweepIndexIsAWholeNumber()
{
    const QString path = writeFile(dir_, QStringLiteral("sweep.json"), fullSetup("han2005", ""));
    const Run r = cli({"sweep", path, "--vary", "shot.heading=0:1:100001", "--shard", "100001/100001", "--jobs", "1"});
    QVERIFY2(r.status == 0, r.err.constData());
    QVERIFY2(r.out.startsWith(R"({ "index": 100000, "set": { "shot.heading": 1 })"), r.out.constData());
    QCOMPARE(r.out.count('\n'), 1);
}

QTEST_GUILESS_MAIN(TestCliContract)
#include "tst_clicontract.moc"
