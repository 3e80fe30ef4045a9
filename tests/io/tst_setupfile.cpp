// Loading what the contract allows, saving in its format and order, and round trips: a setup saved
// and loaded again is bit-identical and simulates to a bit-identical event log.

#include "JsonText.h"
#include "SetupCompare.h"
#include "SetupFile.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

#include <bit>
#include <cmath>
#include <random>

using namespace cuelab;
using cuelab::testing::eventLogDifferences;
using cuelab::testing::setupDifferences;

namespace {

QString examplesDir() { return QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples"); }

Setup parseOrFail(const QByteArray& json)
{
    QString error;
    const std::optional<Setup> setup = io::parseSetup(json, QStringLiteral("test.json"), &error);
    if (!setup) qFatal("%s", qPrintable(error));
    return *setup;
}

// A valid setup with every field away from its default: random values on a random table, balls on
// a jittered grid so that they never overlap each other or a cushion.
Setup randomSetup(std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto in = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
    Setup s;
    s.name = "random \"setup\" \\ ä\n" + std::to_string(rng() % 1000);
    s.notes = "notes\twith\x01 control characters";
    const TableKind kinds[] = {TableKind::Pool9ft, TableKind::Pool8ft, TableKind::Pool7ft, TableKind::Snooker,
                               TableKind::Carom};
    s.table.kind = kinds[rng() % 5];
    if (rng() % 2) s.table.length = makeTable(s.table.kind).length * in(0.95, 1.05);
    if (rng() % 2) s.table.width = makeTable(s.table.kind).width * in(0.95, 1.05);
    if (rng() % 2) s.table.cushionHeight = in(0.033, 0.037);
    s.table.pockets = rng() % 4 != 0;
    PhysicsParams& p = s.physics;
    p.gravity = in(9.7, 9.9);
    p.muSlide = in(0.1, 0.4);
    p.muRoll = in(0.005, 0.015);
    p.muSpin = in(0.005, 0.02);
    p.ballBallModel = rng() % 2 ? BallBallModel::Frictional : BallBallModel::Frictionless;
    p.ballBallRestitution = in(0.9, 1.0);
    p.ballBallFrictionKind = rng() % 2 ? BallBallFriction::Alciatore : BallBallFriction::Fixed;
    p.ballBallFriction = in(0.0, 0.1);
    p.ballCushionModel = BallCushionModel(rng() % 4);  // mirror, han2005, mathavan2010, stronge
    p.cushionRestitution = in(0.6, 0.95);
    p.cushionFriction = in(0.0, 0.3);
    if (p.ballCushionModel == BallCushionModel::Mathavan2010) p.mathavanSteps = double(10 + rng() % 5000);
    if (p.ballCushionModel == BallCushionModel::Stronge) p.strongeOmegaRatio = in(1.01, 1.99);

    const Table table = makeTable(s.table);
    const int count = 1 + static_cast<int>(rng() % 6);
    for (int i = 0; i < count; ++i) {
        Ball b;
        b.id = i == 0 ? "cue" : std::to_string(i);
        if (rng() % 2) b.radius = in(0.0260, 0.0300);
        else b.radius = table.ballRadius;
        if (rng() % 2) b.mass = in(0.14, 0.21);
        else b.mass = table.ballMass;
        // Cells of 0.2 m from 0.3 m off the corner: far from cushions, jaws and each other.
        const double x = 0.3 + 0.2 * (i % 3) + in(-0.05, 0.05);
        const double y = 0.3 + 0.2 * (i / 3) + in(-0.05, 0.05);
        b.state.position = Vec2(x, y);
        if (rng() % 2) b.state.velocity = Vec2(in(-1, 1), in(-1, 1));
        if (rng() % 2) b.state.spin = Vec3(in(-30, 30), in(-30, 30), in(-30, 30));
        b.state.motion = classify(b.state, b.radius);
        s.balls.push_back(b);
    }
    if (rng() % 4 != 0) {
        CueStrike shot;
        shot.ball = "cue";
        shot.speed = in(0.5, 4.0);
        shot.headingDeg = in(-180, 180);
        shot.elevationDeg = in(0, 20);
        shot.side = in(-0.4, 0.4);
        shot.height = in(-0.4, 0.4);
        shot.cueMass = in(0.5, 0.6);
        if (rng() % 2) shot.endMass = in(0.004, 0.01);  // squirt
        s.shot = shot;
    }
    s.simulation.frameDt = in(0.005, 0.05);
    s.simulation.maxTime = in(1.0, 3.0);
    return s;
}

}  // namespace

class TestSetupFile : public QObject {
    Q_OBJECT

private slots:
    void airborneKeys();
    void minimalFileGetsDefaults();
    void everyKeyIsRead();
    void ballDefaultsFollowTheTable();
    void touchingIsAllowed_data();
    void touchingIsAllowed();
    void numbersRoundTrip();
    void keysInContractOrder();
    void roundTripExamples_data();
    void roundTripExamples();
    void roundTripRandomSetups();
    void saveAndLoad();
    void failedSaveKeepsThePreviousFile();
    void unreadableFileIsNamed();
};

void TestSetupFile::minimalFileGetsDefaults()
{
    const Setup s = parseOrFail(R"({"format": "cuelab-setup", "version": 1, "balls": []})");
    const Setup defaults;
    QVERIFY(s.name.empty() && s.notes.empty());
    QCOMPARE(int(s.table.kind), int(TableKind::Pool9ft));
    QVERIFY(!s.table.length && !s.table.width && !s.table.cushionHeight);
    QVERIFY(s.table.pockets);
    QCOMPARE(s.physics.muSlide, defaults.physics.muSlide);
    QCOMPARE(int(s.physics.ballCushionModel), int(BallCushionModel::Han2005));
    QVERIFY(s.balls.empty());
    QVERIFY(!s.shot);
    QCOMPARE(s.simulation.frameDt, defaults.simulation.frameDt);
    QCOMPARE(s.simulation.maxTime, defaults.simulation.maxTime);
}

void TestSetupFile::everyKeyIsRead()
{
    const Setup s = parseOrFail(R"({
      "format": "cuelab-setup", "version": 1.0, "name": "All keys", "notes": "every key set",
      "table": {"kind": "pool-8ft", "length": 2.3, "width": 1.15, "cushion_height": 0.035, "pockets": false},
      "physics": {"gravity": 9.8, "mu_slide": 0.25, "mu_roll": 0.012, "mu_spin": 0.02,
                  "ball_ball": {"model": "frictional", "restitution": 0.93, "friction": "alciatore"},
                  "ball_cushion": {"model": "mirror", "restitution": 0.8, "friction": 0.1}},
      "balls": [{"id": "cue", "position": [0.5, 0.6], "velocity": [0.1, -0.2], "spin": [1, 2, 3],
                 "radius": 0.028, "mass": 0.16}],
      "shot": {"ball": "cue", "speed": 2.5, "heading": -30, "elevation": 5, "side": 0.2, "height": -0.3,
               "cue_mass": 0.55},
      "simulation": {"frame_dt": 0.02, "max_time": 30}})");
    QCOMPARE(s.name, std::string("All keys"));
    QCOMPARE(s.notes, std::string("every key set"));
    QCOMPARE(int(s.table.kind), int(TableKind::Pool8ft));
    QCOMPARE(*s.table.length, 2.3);
    QCOMPARE(*s.table.width, 1.15);
    QCOMPARE(*s.table.cushionHeight, 0.035);
    QVERIFY(!s.table.pockets);
    QCOMPARE(s.physics.gravity, 9.8);
    QCOMPARE(s.physics.muSlide, 0.25);
    QCOMPARE(s.physics.muRoll, 0.012);
    QCOMPARE(s.physics.muSpin, 0.02);
    QCOMPARE(int(s.physics.ballBallModel), int(BallBallModel::Frictional));
    QCOMPARE(s.physics.ballBallRestitution, 0.93);
    QCOMPARE(int(s.physics.ballBallFrictionKind), int(BallBallFriction::Alciatore));
    QCOMPARE(int(s.physics.ballCushionModel), int(BallCushionModel::Mirror));
    QCOMPARE(s.physics.cushionRestitution, 0.8);
    QCOMPARE(s.physics.cushionFriction, 0.1);
    QCOMPARE(s.balls.size(), std::size_t(1));
    const Ball& b = s.balls[0];
    QCOMPARE(b.id, std::string("cue"));
    QCOMPARE(b.state.position, Vec2(0.5, 0.6));
    QCOMPARE(b.state.velocity, Vec2(0.1, -0.2));
    QCOMPARE(b.state.spin, Vec3(1, 2, 3));
    QCOMPARE(int(b.state.motion), int(MotionState::Sliding));
    QCOMPARE(b.radius, 0.028);
    QCOMPARE(b.mass, 0.16);
    QVERIFY(s.shot);
    QCOMPARE(s.shot->ball, std::string("cue"));
    QCOMPARE(s.shot->speed, 2.5);
    QCOMPARE(s.shot->headingDeg, -30.0);  // degrees stay degrees
    QCOMPARE(s.shot->elevationDeg, 5.0);
    QCOMPARE(s.shot->side, 0.2);
    QCOMPARE(s.shot->height, -0.3);
    QCOMPARE(s.shot->cueMass, 0.55);
    QCOMPARE(s.simulation.frameDt, 0.02);
    QCOMPARE(s.simulation.maxTime, 30.0);
}

void TestSetupFile::ballDefaultsFollowTheTable()
{
    const Setup s = parseOrFail(
        R"({"format": "cuelab-setup", "version": 1, "table": {"kind": "carom"}, "balls": [{"id": "white", "position": [1, 0.7]}]})");
    const Table carom = makeTable(TableKind::Carom);
    QCOMPARE(s.balls[0].radius, carom.ballRadius);
    QCOMPARE(s.balls[0].mass, carom.ballMass);
    QCOMPARE(int(s.balls[0].state.motion), int(MotionState::Stationary));
}

void TestSetupFile::touchingIsAllowed_data()
{
    QTest::addColumn<QByteArray>("balls");
    // 2R = 0.05715 m on a 9-ft table.
    QTest::newRow("balls exactly touching") << QByteArray(R"([{"id": "a", "position": [1, 0.6]}, {"id": "b", "position": [1.05715, 0.6]}])");
    QTest::newRow("balls 0.5 nm inside each other") << QByteArray(R"([{"id": "a", "position": [1, 0.6]}, {"id": "b", "position": [1.0571499995, 0.6]}])");
    QTest::newRow("ball touching a rail") << QByteArray(R"([{"id": "a", "position": [0.6, 0.028575]}])");
    QTest::newRow("ball frozen on a closed rail") << QByteArray(R"([{"id": "a", "position": [0.028575, 0.6]}])");
}

void TestSetupFile::touchingIsAllowed()
{
    QFETCH(QByteArray, balls);
    QString error;
    const QByteArray json = R"({"format": "cuelab-setup", "version": 1, "balls": )" + balls + "}";
    QVERIFY2(io::parseSetup(json, QStringLiteral("t.json"), &error), qPrintable(error));
}

void TestSetupFile::numbersRoundTrip()
{
    // The writer's shortest text must read back to the same bits through Qt's JSON parser, for any
    // finite double but negative zero (which Qt reads as +0; documented in SetupWriter.cpp).
    std::vector<double> values{0.1, 1.0 / 3.0, 2.0 / 3.0, 1e-300, 1e300, 5e-324, 2.2250738585072014e-308,
                               1.7976931348623157e308, 9007199254740993.0, 123456789012345678.0, 0.028575,
                               1.0 / 60.0, -2.5e-7, 600.0, 1e23, 4.35e-5};
    std::mt19937_64 rng(20261122);
    for (int i = 0; i < 20000; ++i) {
        const double x = std::bit_cast<double>(rng());
        if (std::isfinite(x)) values.push_back(x);
    }
    std::uniform_real_distribution<double> metres(-3.0, 3.0);
    for (int i = 0; i < 20000; ++i) values.push_back(metres(rng));
    QByteArray array = "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i) array += ',';
        array += QByteArray::fromStdString(io::roundTripNumber(values[i]));
    }
    array += ']';
    QJsonParseError error;
    const QJsonArray parsed = QJsonDocument::fromJson(array, &error).array();
    QCOMPARE(error.error, QJsonParseError::NoError);
    QCOMPARE(parsed.size(), qsizetype(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double back = parsed[qsizetype(i)].toDouble();
        if (values[i] == 0.0) continue;  // the sign of zero does not survive Qt's parser
        QVERIFY2(testing::sameBits(back, values[i]), io::roundTripNumber(values[i]).c_str());
    }
    QCOMPARE(io::roundTripNumber(0.1), std::string("0.1"));
    QCOMPARE(io::roundTripNumber(600.0), std::string("600"));
    QCOMPARE(io::roundTripNumber(std::nan("")), std::string("null"));
}

void TestSetupFile::keysInContractOrder()
{
    std::mt19937_64 rng(7);
    Setup s = randomSetup(rng);
    s.name = "n";
    s.notes = "o";
    CueStrike shot;
    shot.ball = "cue";
    s.shot = shot;
    const QByteArray text = io::serializeSetup(s);
    qsizetype last = -1;
    for (const char* key : {"\"format\"", "\"version\"", "\"name\"", "\"notes\"", "\"table\"", "\"kind\"", "\"pockets\"",
                            "\"physics\"", "\"gravity\"", "\"mu_slide\"", "\"mu_roll\"", "\"mu_spin\"", "\"ball_ball\"",
                            "\"ball_cushion\"", "\"balls\"", "\"id\"", "\"position\"", "\"shot\"", "\"ball\"", "\"speed\"",
                            "\"heading\"", "\"elevation\"", "\"side\"", "\"height\"", "\"cue_mass\"", "\"simulation\"",
                            "\"frame_dt\"", "\"max_time\""}) {
        const qsizetype at = text.indexOf(key, last + 1);
        QVERIFY2(at > last, key);
        last = at;
    }
    QVERIFY(text.endsWith("}\n"));
}

void TestSetupFile::roundTripExamples_data()
{
    QTest::addColumn<QString>("file");
    for (const QString& file : QDir(examplesDir()).entryList({QStringLiteral("*.json")}, QDir::Files))
        QTest::newRow(qPrintable(file)) << file;
}

void TestSetupFile::roundTripExamples()
{
    QFETCH(QString, file);
    QString error;
    const std::optional<Setup> original = io::loadSetup(examplesDir() + QLatin1Char('/') + file, &error);
    QVERIFY2(original, qPrintable(error));
    const QByteArray text = io::serializeSetup(*original);
    const Setup again = parseOrFail(text);
    QCOMPARE(setupDifferences(*original, again), QStringList());
    QCOMPARE(io::serializeSetup(again), text);  // saving is a fixed point
    QCOMPARE(eventLogDifferences(simulate(*original), simulate(again)), QStringList());
}

void TestSetupFile::roundTripRandomSetups()
{
    std::mt19937_64 rng(42);
    for (int i = 0; i < 200; ++i) {
        const Setup original = randomSetup(rng);
        const QByteArray text = io::serializeSetup(original);
        QString error;
        const std::optional<Setup> again = io::parseSetup(text, QStringLiteral("random.json"), &error);
        QVERIFY2(again, qPrintable(error + QLatin1Char('\n') + QString::fromUtf8(text)));
        QCOMPARE(setupDifferences(original, *again).join(QLatin1Char(',')), QString());
        if (i % 10 == 0) {  // the simulation is the expensive part: a sample is enough
            SimulationOptions options;
            options.until = 1.0;
            QCOMPARE(eventLogDifferences(simulate(original, options), simulate(*again, options)), QStringList());
        }
    }
}

void TestSetupFile::saveAndLoad()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    std::mt19937_64 rng(3);
    const Setup original = randomSetup(rng);
    const QString path = dir.filePath(QStringLiteral("saved.json"));
    QString error;
    QVERIFY2(io::saveSetup(original, path, &error), qPrintable(error));
    const std::optional<Setup> loaded = io::loadSetup(path, &error);
    QVERIFY2(loaded, qPrintable(error));
    QCOMPARE(setupDifferences(original, *loaded).join(QLatin1Char(',')), QString());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), io::serializeSetup(original));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{QStringLiteral("saved.json")});
}

void TestSetupFile::failedSaveKeepsThePreviousFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lesson.json"));
    std::mt19937_64 rng(5);
    Setup setup = randomSetup(rng);
    QString error;
    QVERIFY(io::saveSetup(setup, path, &error));
    QFile before(path);
    QVERIFY(before.open(QIODevice::ReadOnly));
    const QByteArray previous = before.readAll();
    before.close();

    // A setup that would not load again is not written: the previous file stays as it was.
    setup.balls.push_back(setup.balls.front());
    QVERIFY(!io::saveSetup(setup, path, &error));
    QVERIFY2(error.startsWith(QStringLiteral("not saved: lesson.json: balls[")), qPrintable(error));
    QFile after(path);
    QVERIFY(after.open(QIODevice::ReadOnly));
    QCOMPARE(after.readAll(), previous);

    // Nowhere to write: a missing folder, a path that is a folder.
    setup.balls.pop_back();
    QVERIFY(!io::saveSetup(setup, dir.filePath(QStringLiteral("missing/lesson.json")), &error));
    QVERIFY2(error.startsWith(QStringLiteral("lesson.json: cannot save")), qPrintable(error));
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("folder.json")));
    QVERIFY(!io::saveSetup(setup, dir.filePath(QStringLiteral("folder.json")), &error));
    QVERIFY2(error.startsWith(QStringLiteral("folder.json: cannot save")), qPrintable(error));
}

void TestSetupFile::unreadableFileIsNamed()
{
    QString error;
    QVERIFY(!io::loadSetup(QStringLiteral("/nonexistent/rack.json"), &error));
    QVERIFY2(error.startsWith(QStringLiteral("rack.json: cannot read")), qPrintable(error));
}

void TestSetupFile::airborneKeys()
{
    // CONTRACT.md "Airborne balls": a ball's z and vz, physics.ball_table; written back only when not
    // the defaults, so that a file without them is written as before.
    const QByteArray text = R"({"format": "cuelab-setup", "version": 1, "name": "air",
        "physics": {"ball_table": {"model": "frictionless", "restitution": 0.4, "friction": 0.3}},
        "balls": [{"id": "cue", "position": [1, 0.6], "z": 0.1, "vz": -0.5}, {"id": "1", "position": [2, 0.6]}]})";
    QString error;
    const std::optional<Setup> s = io::parseSetup(text, QStringLiteral("air.json"), &error);
    QVERIFY2(s, qPrintable(error));
    QCOMPARE(s->balls[0].state.z, 0.1);
    QCOMPARE(s->balls[0].state.vz, -0.5);
    QVERIFY(s->balls[0].state.motion == MotionState::Airborne);
    QCOMPARE(s->balls[1].state.z, 0.0);
    QVERIFY(s->physics.ballTableModel == BallTableModel::Frictionless);
    QCOMPARE(s->physics.tableRestitution, 0.4);
    QCOMPARE(s->physics.tableFriction, 0.3);
    const QByteArray written = io::serializeSetup(*s);
    QVERIFY(written.contains("\"ball_table\""));
    const std::optional<Setup> again = io::parseSetup(written, QStringLiteral("again.json"), &error);
    QVERIFY2(again, qPrintable(error));
    QCOMPARE(again->balls[0].state.z, 0.1);
    QCOMPARE(again->balls[0].state.vz, -0.5);
    QCOMPARE(again->physics.tableRestitution, 0.4);
    // Without them: no new key is written.
    Setup plain = *s;
    plain.physics = PhysicsParams{};
    plain.balls[0].state.z = 0.0;
    plain.balls[0].state.vz = 0.0;
    const QByteArray old = io::serializeSetup(plain);
    QVERIFY(!old.contains("ball_table"));
    QVERIFY(!old.contains("\"z\""));
    QVERIFY(!old.contains("\"vz\""));
    // Under the cloth is refused.
    QByteArray under = text;
    under.replace("\"z\": 0.1", "\"z\": -0.01");
    QVERIFY(!io::parseSetup(under, QStringLiteral("under.json"), &error));
    QVERIFY2(error.contains(QLatin1String("balls[0].z")), qPrintable(error));
}

QTEST_GUILESS_MAIN(TestSetupFile)
#include "tst_setupfile.moc"
