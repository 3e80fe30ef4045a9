// cuelab-cli as users and scripts run it (QProcess on the built binary): CONTRACT.md's commands,
// outputs that parse with the right shape, exit statuses, byte-identical repeated runs.

#include "Cli.h"
#include "Table.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

namespace {

const QString kBinary = QStringLiteral(CUELAB_BINARY_DIR "/bin/cuelab-cli");
const QString kExamples = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/");

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

QString example(const char* name) { return kExamples + QLatin1String(name); }

QJsonObject parseObject(const QByteArray& text)
{
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(text, &error);
    if (error.error != QJsonParseError::NoError || !document.isObject())
        qFatal("not a JSON object: %s", qPrintable(error.errorString()));
    return document.object();
}

const QSet<QString> kStates{"stationary", "spinning", "sliding", "rolling", "pocketed", "airborne", "off-table"};
const QSet<QString> kEventTypes{"cue-strike",   "ball-ball",    "ball-cushion", "ball-pocket",  "slide-to-roll",
                                "roll-to-spin", "roll-to-stop", "spin-to-stop", "slide-to-spin", "slide-to-stop"};

bool isNumberArray(const QJsonValue& v, int size)
{
    if (!v.isArray() || v.toArray().size() != size) return false;
    for (const QJsonValue& x : v.toArray())
        if (!x.isDouble()) return false;
    return true;
}

// A ball state object of CONTRACT.md; returns what is wrong with it (empty: fine).
QString checkBallState(const QJsonValue& value)
{
    const QJsonObject o = value.toObject();
    QStringList keys{"id", "state", "position", "velocity", "spin", "z", "vz"};  // z, vz: CONTRACT.md "Airborne balls"
    if (o.value("state").toString() == QLatin1String("pocketed")) keys << "pocket";
    QStringList actual = o.keys();
    actual.sort();
    keys.sort();
    if (actual != keys) return QStringLiteral("keys ") + actual.join(',');
    if (!o.value("id").isString()) return QStringLiteral("id");
    if (!kStates.contains(o.value("state").toString())) return QStringLiteral("state");
    if (!isNumberArray(o.value("position"), 2) || !isNumberArray(o.value("velocity"), 2) || !isNumberArray(o.value("spin"), 3))
        return QStringLiteral("vectors");
    if (!o.value("z").isDouble() || !o.value("vz").isDouble()) return QStringLiteral("height");
    return {};
}

QString writeFile(const QTemporaryDir& dir, const char* name, const QByteArray& text)
{
    const QString path = dir.filePath(QLatin1String(name));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size()) qFatal("cannot write %s", name);
    return path;
}

// A shot that is still rolling at 0.5 s and rests after about 2.6 s.
const QByteArray kRolling = R"({"format": "cuelab-setup", "version": 1, "name": "rolling",
    "balls": [{"id": "cue", "position": [0.5, 0.6]}, {"id": "8", "position": [2.0, 0.3]}],
    "shot": {"ball": "cue", "speed": 1.0, "heading": 0, "elevation": 0, "side": 0, "height": 0}%1})";

QByteArray rolling(const char* extra = "") { return QString::fromLatin1(kRolling).arg(QLatin1String(extra)).toUtf8(); }

}  // namespace

class TestCli : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void help();
    void version();
    void usageErrors_data();
    void usageErrors();
    void refusedSetups_data();
    void refusedSetups();
    void validateExamples();
    void simulateOutput_data();
    void simulateOutput();
    void jawIsACushion();
    void simulateUntil();
    void unfinished_data();
    void unfinished();
    void stateMatchesEvents();
    void stateBeyondAnUnfinishedRun();
    void trajectoryCsv_data();
    void trajectoryCsv();
    void trajectoryFrameCap();
    void repeatedRunsAreByteIdentical_data();
    void repeatedRunsAreByteIdentical();
    void libraryMatchesBinary();

private:
    QTemporaryDir dir_;
};

void TestCli::initTestCase()
{
    QVERIFY2(QFile::exists(kBinary), qPrintable(kBinary));
    QVERIFY(dir_.isValid());
}

void TestCli::help()
{
    const Run r = cli({"--help"});
    QCOMPARE(r.status, 0);
    QVERIFY(r.err.isEmpty());
    QVERIFY(r.out.startsWith("Usage: cuelab-cli [options] command setup\n"));
    for (const char* text : {"validate SETUP", "simulate SETUP [--until T]", "state SETUP --at T",
                             "trajectory SETUP [--frame-dt S] [--until T]", "--max-events", "Exit status"})
        QVERIFY2(r.out.contains(text), text);
}

void TestCli::version()
{
    const Run r = cli({"--version"});
    QCOMPARE(r.status, 0);
    QVERIFY2(QRegularExpression(QStringLiteral("^cuelab-cli \\d+\\.\\d+\\.\\d+\\n$")).match(QString::fromUtf8(r.out)).hasMatch(),
             r.out.constData());
}

void TestCli::usageErrors_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("fragment");
    const QString setup = example("stun-shot.json");
    QTest::newRow("nothing") << QStringList{} << "no command";
    QTest::newRow("unknown command") << QStringList{"run", setup} << "unknown command 'run'";
    QTest::newRow("no setup") << QStringList{"validate"} << "no setup file";
    QTest::newRow("two setups") << QStringList{"validate", setup, setup} << "unexpected argument";
    QTest::newRow("unknown option") << QStringList{"simulate", setup, "--fast"} << "Unknown option 'fast'";
    QTest::newRow("option without value") << QStringList{"simulate", setup, "--until"} << "Missing value";
    QTest::newRow("--at on simulate") << QStringList{"simulate", setup, "--at", "1"} << "--at is not an option";
    QTest::newRow("--until on validate") << QStringList{"validate", setup, "--until", "1"} << "--until is not an option";
    QTest::newRow("--frame-dt on state") << QStringList{"state", setup, "--at", "1", "--frame-dt", "0.1"}
                                         << "--frame-dt is not an option";
    QTest::newRow("--max-events on validate") << QStringList{"validate", setup, "--max-events", "9"} << "--max-events";
    QTest::newRow("state without --at") << QStringList{"state", setup} << "--at T is required";
    QTest::newRow("negative time") << QStringList{"simulate", setup, "--until", "-1"} << "--until: expected a number";
    QTest::newRow("time not a number") << QStringList{"state", setup, "--at", "soon"} << "--at: expected a number";
    QTest::newRow("time infinite") << QStringList{"state", setup, "--at", "inf"} << "--at: expected a number";
    QTest::newRow("zero frame step") << QStringList{"trajectory", setup, "--frame-dt", "0"} << "--frame-dt: expected";
    QTest::newRow("zero event cap") << QStringList{"simulate", setup, "--max-events", "0"} << "--max-events: expected";
}

void TestCli::usageErrors()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, fragment);
    const Run r = cli(arguments);
    QCOMPARE(r.status, 2);
    QVERIFY(r.out.isEmpty());
    QVERIFY2(r.err.startsWith("cuelab-cli: ") && QString::fromUtf8(r.err).contains(fragment), r.err.constData());
}

void TestCli::refusedSetups_data()
{
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("message");  // the start of stderr
    const QString overlap = writeFile(dir_, "rack.json", R"({"format": "cuelab-setup", "version": 1, "balls": [
        {"id": "7", "position": [1.0, 0.6]}, {"id": "cue", "position": [1.0550499, 0.6]}]})");
    const QString future = writeFile(dir_, "future.json", R"({"format": "cuelab-setup", "version": 2, "balls": []})");
    const QString broken = writeFile(dir_, "broken.json", "{\"format\": \"cuelab-setup\",\n\"version\": 1,,}");
    for (const char* command : {"validate", "simulate", "state", "trajectory"}) {
        const QString c = QLatin1String(command);
        QTest::newRow(qPrintable(c + " overlap")) << c << overlap
                                                  << "cuelab-cli: rack.json: balls[1].position: ball \"cue\" overlaps ball \"7\" by 2.1 mm\n";
        QTest::newRow(qPrintable(c + " version")) << c << future << "cuelab-cli: future.json: version: version 2";
        QTest::newRow(qPrintable(c + " not JSON")) << c << broken << "cuelab-cli: broken.json: line 2, column 15: not valid JSON";
        QTest::newRow(qPrintable(c + " missing")) << c << dir_.filePath("missing.json")
                                                  << "cuelab-cli: missing.json: cannot read the file";
    }
}

void TestCli::refusedSetups()
{
    QFETCH(QString, command);
    QFETCH(QString, file);
    QFETCH(QString, message);
    QStringList arguments{command, file};
    if (command == QLatin1String("state")) arguments << "--at" << "1";
    const Run r = cli(arguments);
    QCOMPARE(r.status, 1);
    QVERIFY(r.out.isEmpty());
    QVERIFY2(r.err.startsWith(message.toUtf8()), r.err.constData());
}

void TestCli::validateExamples()
{
    for (const char* name : {"straight-shot.json", "8-ball-break.json", "snooker-plant.json", "three-cushion.json"}) {
        const Run r = cli({"validate", example(name)});
        QCOMPARE(r.status, 0);
        QVERIFY(r.out.isEmpty());
        QVERIFY(r.err.isEmpty());
    }
}

void TestCli::simulateOutput_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("balls");
    QTest::newRow("half-ball cut (pocket, cushion)") << example("half-ball-cut.json") << 2;
    QTest::newRow("8-ball break (simultaneous events)") << example("8-ball-break.json") << 16;
    QTest::newRow("one-cushion bank") << example("one-cushion-bank.json") << 2;
}

void TestCli::simulateOutput()
{
    QFETCH(QString, file);
    QFETCH(int, balls);
    const Run r = cli({"simulate", file});
    QCOMPARE(r.status, 0);
    QVERIFY(r.err.isEmpty());
    // Keys in the contract's order.
    QVERIFY(r.out.indexOf("\"end_time\"") < r.out.indexOf("\"events\""));
    QVERIFY(r.out.indexOf("\"events\"") < r.out.lastIndexOf("\"balls\": ["));
    const QJsonObject o = parseObject(r.out);
    QCOMPARE(o.keys(), (QStringList{"balls", "end_time", "events", "outcome"}));

    const QJsonArray events = o.value("events").toArray();
    QVERIFY(!events.isEmpty());
    QCOMPARE(events.first().toObject().value("type").toString(), QStringLiteral("cue-strike"));
    double previous = 0.0;
    for (const QJsonValue& v : events) {
        const QJsonObject e = v.toObject();
        const QString type = e.value("type").toString();
        QVERIFY2(kEventTypes.contains(type), qPrintable(type));
        const double time = e.value("time").toDouble(-1.0);
        QVERIFY(time >= previous);  // time order
        previous = time;
        const int agents = type == QLatin1String("ball-ball") ? 2 : 1;
        QCOMPARE(e.value("balls").toArray().size(), agents);
        QStringList expectedKeys{"time", "type", "balls", "before", "after"};
        if (type == QLatin1String("ball-cushion")) {
            expectedKeys << "cushion";
            QVERIFY(QRegularExpression("^(rail|facing|jaw)-").match(e.value("cushion").toString()).hasMatch());
        }
        if (type == QLatin1String("ball-pocket")) {
            expectedKeys << "pocket";
            QVERIFY(e.value("pocket").toString().startsWith(QLatin1String("pocket-")));
        }
        QStringList keys = e.keys();
        keys.sort();
        expectedKeys.sort();
        QCOMPARE(keys, expectedKeys);
        for (const char* side : {"before", "after"}) {
            const QJsonArray states = e.value(side).toArray();
            QCOMPARE(states.size(), agents);
            for (int i = 0; i < agents; ++i) {
                QCOMPARE(checkBallState(states[i]), QString());
                QCOMPARE(states[i].toObject().value("id"), e.value("balls").toArray()[i]);
            }
        }
    }
    QCOMPARE(o.value("end_time").toDouble(), previous);  // rests at the last event
    const QJsonArray finalStates = o.value("balls").toArray();
    QCOMPARE(finalStates.size(), balls);
    for (const QJsonValue& b : finalStates) {
        QCOMPARE(checkBallState(b), QString());
        const QString state = b.toObject().value("state").toString();
        QVERIFY(state == QLatin1String("stationary") || state == QLatin1String("pocketed"));
    }
}

void TestCli::jawIsACushion()
{
    // A ball sent straight down onto the rounded tip of the bottom side pocket's left jaw, 4 mm on
    // the pocket's side of where the rail ends: a ball-jaw contact, written as a ball-cushion event
    // that names the jaw.
    const cuelab::Table table = cuelab::makeTable(cuelab::TableKind::Pool9ft);
    const cuelab::JawTip* jaw = nullptr;
    for (const cuelab::JawTip& j : table.jaws)
        if (j.id == "jaw-b-left") jaw = &j;
    QVERIFY(jaw);
    const QByteArray json = QStringLiteral(R"({"format": "cuelab-setup", "version": 1, "balls": [
        {"id": "1", "position": [%1, 0.4], "velocity": [0, -1]}]})")
                                .arg(jaw->centre.x() + 0.004, 0, 'g', 17)
                                .toUtf8();
    const Run r = cli({"simulate", writeFile(dir_, "jaw.json", json)});
    QCOMPARE(r.status, 0);
    const QJsonArray events = parseObject(r.out).value("events").toArray();
    bool hit = false;
    for (const QJsonValue& e : events) {
        if (e.toObject().value("type").toString() != QLatin1String("ball-cushion")) continue;
        QCOMPARE(e.toObject().value("cushion").toString(), QStringLiteral("jaw-b-left"));
        hit = true;
        break;
    }
    QVERIFY(hit);
}

void TestCli::simulateUntil()
{
    const Run r = cli({"simulate", writeFile(dir_, "rolling.json", rolling()), "--until", "0.5"});
    QCOMPARE(r.status, 0);
    const QJsonObject o = parseObject(r.out);
    QCOMPARE(o.value("end_time").toDouble(), 0.5);
    for (const QJsonValue& e : o.value("events").toArray()) QVERIFY(e.toObject().value("time").toDouble() <= 0.5);
    QCOMPARE(o.value("balls").toArray()[0].toObject().value("state").toString(), QStringLiteral("rolling"));
}

void TestCli::unfinished_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("fragment");
    const QString shortRun = writeFile(dir_, "short.json", rolling(R"(, "simulation": {"max_time": 0.5})"));
    QTest::newRow("max_time before rest") << QStringList{"simulate", shortRun} << "balls still move at max_time = 0.5 s";
    QTest::newRow("--until beyond max_time") << QStringList{"simulate", shortRun, "--until", "10"} << "max_time";
    QTest::newRow("trajectory, max_time") << QStringList{"trajectory", shortRun} << "max_time";
    QTest::newRow("event cap") << QStringList{"simulate", example("8-ball-break.json"), "--max-events", "3"}
                               << "cut short";
    QTest::newRow("event cap, trajectory") << QStringList{"trajectory", example("8-ball-break.json"), "--max-events", "3"}
                                           << "cut short";
}

void TestCli::unfinished()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, fragment);
    const Run r = cli(arguments);
    QCOMPARE(r.status, 3);
    QVERIFY2(QString::fromUtf8(r.err).contains(fragment), r.err.constData());
    // What was computed is still printed, complete and well-formed.
    QVERIFY(!r.out.isEmpty());
    if (arguments.first() == QLatin1String("simulate")) parseObject(r.out);
    else QVERIFY(r.out.startsWith("time,ball,state,x,y,vx,vy,wx,wy,wz,z,vz\n") && r.out.endsWith('\n'));
}

void TestCli::stateMatchesEvents()
{
    // At an event's time the state is the one just after the event: byte for byte the numbers of
    // the event's "after" list.
    const QString file = example("half-ball-cut.json");
    const QJsonObject simulation = parseObject(cli({"simulate", file}).out);
    const QJsonArray events = simulation.value("events").toArray();
    for (const int index : {0, 1, int(events.size()) - 1}) {
        const QJsonObject event = events[index].toObject();
        // 17 significant digits give back the very double the tool printed.
        const Run r = cli({"state", file, "--at", QString::number(event.value("time").toDouble(), 'g', 17)});
        QCOMPARE(r.status, 0);
        const QJsonObject state = parseObject(r.out);
        QCOMPARE(state.value("time").toDouble(), event.value("time").toDouble());
        for (const QJsonValue& after : event.value("after").toArray()) {
            bool found = false;
            for (const QJsonValue& ball : state.value("balls").toArray()) {
                if (ball.toObject().value("id") != after.toObject().value("id")) continue;
                QCOMPARE(ball.toObject(), after.toObject());
                found = true;
            }
            QVERIFY(found);
        }
    }
    // At the end everything rests where `simulate` left it.
    const Run end = cli({"state", file, "--at", "100"});
    QCOMPARE(end.status, 0);
    QCOMPARE(parseObject(end.out).value("balls"), simulation.value("balls"));
}

void TestCli::stateBeyondAnUnfinishedRun()
{
    const QString shortRun = writeFile(dir_, "short-state.json", rolling(R"(, "simulation": {"max_time": 0.5})"));
    const Run inside = cli({"state", shortRun, "--at", "0.25"});
    QCOMPARE(inside.status, 0);
    QCOMPARE(parseObject(inside.out).value("time").toDouble(), 0.25);
    const Run beyond = cli({"state", shortRun, "--at", "1"});
    QCOMPARE(beyond.status, 3);
    QVERIFY(beyond.out.isEmpty());  // no guess
    QVERIFY(beyond.err.contains("max_time"));
}

void TestCli::trajectoryCsv_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<double>("frameDt");
    QTest::newRow("file's frame step") << example("half-ball-cut.json") << QStringList{} << 1.0 / 60.0;
    QTest::newRow("--frame-dt 0.25") << example("stun-cut.json") << QStringList{"--frame-dt", "0.25"} << 0.25;
    QTest::newRow("--until 1") << example("9-ball-break.json") << QStringList{"--until", "1", "--frame-dt", "0.1"} << 0.1;
}

void TestCli::trajectoryCsv()
{
    QFETCH(QString, file);
    QFETCH(QStringList, options);
    QFETCH(double, frameDt);
    QStringList simulateOptions;
    if (options.contains(QStringLiteral("--until"))) simulateOptions << "--until" << "1";
    const QJsonObject simulation = parseObject(cli(QStringList{"simulate", file} + simulateOptions).out);
    const double endTime = simulation.value("end_time").toDouble();
    const qsizetype ballCount = simulation.value("balls").toArray().size();

    const Run r = cli(QStringList{"trajectory", file} + options);
    QCOMPARE(r.status, 0);
    QVERIFY(r.err.isEmpty());
    const QList<QByteArray> lines = r.out.split('\n');
    QCOMPARE(lines.first(), QByteArray("time,ball,state,x,y,vx,vy,wx,wy,wz,z,vz"));
    QVERIFY(lines.last().isEmpty());  // the text ends with a newline

    QList<double> times;  // distinct, in order
    QHash<double, int> rowsAt;
    QSet<QByteArray> pocketedBalls;
    for (qsizetype i = 1; i + 1 < lines.size(); ++i) {
        const QList<QByteArray> fields = lines[i].split(',');
        QCOMPARE(fields.size(), 12);
        bool ok = false;
        const double t = fields[0].toDouble(&ok);
        QVERIFY(ok && t >= 0.0 && t <= endTime);
        if (times.isEmpty() || times.last() != t) {
            QVERIFY(times.isEmpty() || t > times.last());
            times << t;
        }
        ++rowsAt[t];
        QVERIFY(kStates.contains(QString::fromUtf8(fields[2])));
        // A pocketed ball stays pocketed and keeps its row.
        if (fields[2] == "pocketed") pocketedBalls.insert(fields[1]);
        else QVERIFY(!pocketedBalls.contains(fields[1]));
        for (int k = 3; k < 10; ++k) {
            const double x = fields[k].toDouble(&ok);
            QVERIFY(ok && std::isfinite(x));
        }
    }
    for (const double t : times) QCOMPARE(rowsAt[t], int(ballCount));  // one row per ball at each time

    // The times are exactly the frames k * frameDt (to 15 significant digits, so 3 * 0.1 is 0.3)
    // up to the end, and every event time.
    auto frame = [&](long long k) { return QString::number(double(k) * frameDt, 'g', 15).toDouble(); };
    QSet<double> expected;
    for (long long k = 0; frame(k) <= endTime; ++k) expected.insert(frame(k));
    for (const QJsonValue& e : simulation.value("events").toArray()) expected.insert(e.toObject().value("time").toDouble());
    QCOMPARE(QSet<double>(times.begin(), times.end()), expected);
}

void TestCli::trajectoryFrameCap()
{
    const Run r = cli({"trajectory", example("stun-shot.json"), "--frame-dt", "1e-12"});
    QCOMPARE(r.status, 2);
    QVERIFY(r.out.isEmpty());
    QVERIFY(r.err.contains("choose a larger --frame-dt"));
}

void TestCli::repeatedRunsAreByteIdentical_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("simulate 8-ball break") << QStringList{"simulate", example("8-ball-break.json")};
    QTest::newRow("simulate cradle") << QStringList{"simulate", example("newtons-cradle.json")};
    QTest::newRow("state 9-ball break") << QStringList{"state", example("9-ball-break.json"), "--at", "0.75"};
    QTest::newRow("trajectory three-cushion") << QStringList{"trajectory", example("three-cushion.json")};
}

void TestCli::repeatedRunsAreByteIdentical()
{
    QFETCH(QStringList, arguments);
    const Run first = cli(arguments);
    const Run second = cli(arguments);
    QCOMPARE(first.status, 0);
    QVERIFY(first.out.size() > 100);
    QVERIFY(first.out == second.out);
    QCOMPARE(second.status, 0);
}

void TestCli::libraryMatchesBinary()
{
    // Tests and tools may call cuelab::cli::run directly: it prints the same bytes as the binary.
    const QStringList arguments{"simulate", example("two-rail-kick.json")};
    QByteArray out, err;
    const int status = cuelab::cli::run(QStringList{"cuelab-cli"} + arguments, &out, &err);
    const Run r = cli(arguments);
    QCOMPARE(status, r.status);
    QVERIFY(out == r.out);
    QCOMPARE(err, r.err);
}

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
