// Every way CONTRACT.md (version 1) refuses a setup file, one named row each: the message must name
// the file and the JSON path of the culprit, and nothing may be half-loaded.

#include "SetupFile.h"
#include "SetupGeometry.h"

#include <QTest>

using namespace cuelab;

namespace {

// A valid setup: two balls on a 9-ft table and a shot. `members` are spliced in after "version".
QByteArray withMembers(const char* members, const char* balls = nullptr)
{
    const QByteArray ballList = balls ? QByteArray(balls)
                                      : QByteArray(R"([{"id": "cue", "position": [0.6, 0.6]},
                                                      {"id": "1", "position": [1.8, 0.6]}])");
    QByteArray text = R"({"format": "cuelab-setup", "version": 1, )";
    if (members && *members) text += QByteArray(members) + ", ";
    return text + R"("balls": )" + ballList + "}";
}

QByteArray withBalls(const char* balls) { return withMembers("", balls); }

QByteArray withShot(const char* shot) { return withMembers((QByteArray(R"("shot": )") + shot).constData()); }

const char* const kShot = R"({"ball": "cue", "speed": 2, "heading": 0, "elevation": 0, "side": 0, "height": 0)";

}  // namespace

class TestSetupRefusals : public QObject {
    Q_OBJECT

private slots:
    void refused_data();
    void refused();
    void notJsonSaysLineAndColumn_data();
    void notJsonSaysLineAndColumn();
    void overlapAmountIsReadable();
    void validBaseLoads();
    void nullErrorPointerIsAllowed();
};

void TestSetupRefusals::refused_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("path");      // the JSON path the message must name ("" = whole document)
    QTest::addColumn<QString>("fragment");  // a piece of the explanation

    // The document and its header.
    QTest::newRow("top level is an array") << QByteArray("[]") << "" << "JSON object at the top level";
    QTest::newRow("format missing") << QByteArray(R"({"version": 1, "balls": []})") << "format" << "missing";
    QTest::newRow("format wrong") << QByteArray(R"({"format": "pooltool", "version": 1, "balls": []})") << "format"
                                  << "expected \"cuelab-setup\"";
    QTest::newRow("format not a string") << QByteArray(R"({"format": 1, "version": 1, "balls": []})") << "format"
                                         << "expected a string";
    QTest::newRow("version missing") << QByteArray(R"({"format": "cuelab-setup", "balls": []})") << "version"
                                     << "missing";
    QTest::newRow("version 2") << QByteArray(R"({"format": "cuelab-setup", "version": 2, "balls": []})")
                               << "version" << "version 2 is not supported";
    QTest::newRow("version 1.5") << QByteArray(R"({"format": "cuelab-setup", "version": 1.5, "balls": []})")
                                 << "version" << "not supported";
    QTest::newRow("version as text") << QByteArray(R"({"format": "cuelab-setup", "version": "1", "balls": []})")
                                     << "version" << "expected a number";
    QTest::newRow("balls missing") << QByteArray(R"({"format": "cuelab-setup", "version": 1})") << "balls"
                                   << "missing";
    QTest::newRow("duplicate top-level key") << QByteArray("{\"format\": \"cuelab-setup\", \"version\": 1,\n\"name\": \"a\",\n\"name\": \"b\", \"balls\": []}")
                                             << "name" << "duplicate key (the first one is on line 2)";
    QTest::newRow("duplicate key in a ball") << withBalls(R"([{"id": "cue", "position": [0.6, 0.6]},
                                                             {"id": "1", "position": [1.8, 0.6], "radius": 0.03, "radius": 0.02}])")
                                             << "balls[1].radius" << "duplicate key";
    QTest::newRow("duplicate key, one escaped") << withMembers(R"("physics": {"ball_ball": {"model": "frictional", "mod\u0065l": "frictionless"}})")
                                                << "physics.ball_ball.model" << "duplicate key";
    QTest::newRow("unknown top-level key") << withMembers(R"("colour": "green")") << "colour" << "unknown key";
    QTest::newRow("notes written for: a number") << withMembers(R"("lesson": {"notes_written_for": 3})")
                                                 << "lesson.notes_written_for" << "expected a shot code";
    QTest::newRow("notes written for: a broken code") << withMembers(R"("lesson": {"notes_written_for": "cuelab:1:AAAA"})")
                                                      << "lesson.notes_written_for" << "not a shot code CueLab can read";
    QTest::newRow("name not a string") << withMembers(R"("name": 3)") << "name" << "expected a string";
    QTest::newRow("notes null") << withMembers(R"("notes": null)") << "notes" << "found null";

    // table
    QTest::newRow("table not an object") << withMembers(R"("table": [])") << "table" << "expected an object";
    QTest::newRow("table unknown key") << withMembers(R"("table": {"kidn": "snooker"})") << "table.kidn"
                                       << "unknown key";
    QTest::newRow("table kind unknown") << withMembers(R"("table": {"kind": "pool-10ft"})") << "table.kind"
                                        << "unknown table kind";
    QTest::newRow("table kind not a string") << withMembers(R"("table": {"kind": 9})") << "table.kind"
                                             << "expected a string";
    QTest::newRow("table length zero") << withMembers(R"("table": {"length": 0})") << "table.length"
                                       << "greater than 0";
    QTest::newRow("table width negative") << withMembers(R"("table": {"width": -1.27})") << "table.width"
                                          << "greater than 0";
    QTest::newRow("table cushion height zero") << withMembers(R"("table": {"cushion_height": 0})")
                                               << "table.cushion_height" << "greater than 0";
    QTest::newRow("table pockets not a bool") << withMembers(R"("table": {"pockets": "yes"})") << "table.pockets"
                                              << "expected true or false";
    QTest::newRow("table too short for its pockets")
        << withMembers(R"("table": {"length": 0.3, "width": 1.27})", R"([])") << "table.length" << "too short";
    QTest::newRow("table too narrow for its pockets")
        << withMembers(R"("table": {"width": 0.1})", R"([])") << "table.width" << "too narrow";
    QTest::newRow("cushion above the balls")
        << withMembers(R"("table": {"cushion_height": 0.06})") << "balls[0].radius" << "lower than the cushion";

    // physics
    QTest::newRow("physics unknown key") << withMembers(R"("physics": {"mu_slid": 0.2})") << "physics.mu_slid"
                                         << "unknown key";
    QTest::newRow("gravity zero") << withMembers(R"("physics": {"gravity": 0})") << "physics.gravity"
                                  << "greater than 0";
    QTest::newRow("mu_slide negative") << withMembers(R"("physics": {"mu_slide": -0.2})") << "physics.mu_slide"
                                       << "greater than 0";
    QTest::newRow("mu_roll zero") << withMembers(R"("physics": {"mu_roll": 0})") << "physics.mu_roll"
                                  << "greater than 0";
    QTest::newRow("mu_spin as text") << withMembers(R"("physics": {"mu_spin": "low"})") << "physics.mu_spin"
                                     << "expected a number, found a string";
    QTest::newRow("ball_ball not an object") << withMembers(R"("physics": {"ball_ball": 0.95})")
                                             << "physics.ball_ball" << "expected an object";
    QTest::newRow("ball_ball unknown key") << withMembers(R"("physics": {"ball_ball": {"modle": "frictional"}})")
                                           << "physics.ball_ball.modle" << "unknown key";
    QTest::newRow("ball_ball model unknown") << withMembers(R"("physics": {"ball_ball": {"model": "elastic"}})")
                                             << "physics.ball_ball.model" << "unknown model \"elastic\"";
    QTest::newRow("ball_ball restitution above 1")
        << withMembers(R"("physics": {"ball_ball": {"restitution": 1.5}})") << "physics.ball_ball.restitution"
        << "between 0 and 1";
    QTest::newRow("ball_ball restitution below 0")
        << withMembers(R"("physics": {"ball_ball": {"restitution": -0.1}})") << "physics.ball_ball.restitution"
        << "between 0 and 1";
    QTest::newRow("ball_ball friction negative")
        << withMembers(R"("physics": {"ball_ball": {"friction": -0.01}})") << "physics.ball_ball.friction"
        << "must not be negative";
    QTest::newRow("ball_ball friction unknown fit")
        << withMembers(R"("physics": {"ball_ball": {"friction": "coulomb"}})") << "physics.ball_ball.friction"
        << "\"alciatore\"";
    QTest::newRow("ball_ball friction bool")
        << withMembers(R"("physics": {"ball_ball": {"friction": true}})") << "physics.ball_ball.friction"
        << "found true/false";
    QTest::newRow("ball_cushion unknown key")
        << withMembers(R"("physics": {"ball_cushion": {"restitutoin": 0.8}})") << "physics.ball_cushion.restitutoin"
        << "unknown key";
    QTest::newRow("ball_cushion model unknown")
        << withMembers(R"("physics": {"ball_cushion": {"model": "mathavan_2010"}})") << "physics.ball_cushion.model"
        << "unknown model";
    QTest::newRow("ball_cushion restitution above 1")
        << withMembers(R"("physics": {"ball_cushion": {"restitution": 2}})") << "physics.ball_cushion.restitution"
        << "between 0 and 1";
    QTest::newRow("ball_cushion friction negative")
        << withMembers(R"("physics": {"ball_cushion": {"friction": -1}})") << "physics.ball_cushion.friction"
        << "must not be negative";

    // balls
    QTest::newRow("balls not an array") << withBalls(R"({"id": "cue"})") << "balls" << "expected an array";
    QTest::newRow("ball not an object") << withBalls(R"([[0.5, 0.5]])") << "balls[0]" << "expected an object";
    QTest::newRow("ball unknown key") << withBalls(R"([{"id": "cue", "position": [0.6, 0.6]},
                                                       {"id": "1", "position": [1.8, 0.6], "velocty": [1, 0]}])")
                                      << "balls[1].velocty" << "unknown key";
    QTest::newRow("id missing") << withBalls(R"([{"position": [0.6, 0.6]}])") << "balls[0].id" << "missing";
    QTest::newRow("id empty") << withBalls(R"([{"id": "", "position": [0.6, 0.6]}])") << "balls[0].id"
                              << "must not be empty";
    QTest::newRow("id a number") << withBalls(R"([{"id": 7, "position": [0.6, 0.6]}])") << "balls[0].id"
                                 << "expected a string";
    QTest::newRow("id duplicate") << withBalls(R"([{"id": "7", "position": [0.6, 0.6]},
                                                   {"id": "cue", "position": [1.0, 0.6]},
                                                   {"id": "7", "position": [1.8, 0.6]}])")
                                  << "balls[2].id" << "duplicate id \"7\"";
    QTest::newRow("position missing") << withBalls(R"([{"id": "cue"}])") << "balls[0].position" << "missing";
    QTest::newRow("position three numbers") << withBalls(R"([{"id": "cue", "position": [0.6, 0.6, 0.0]}])")
                                            << "balls[0].position" << "expected 2 numbers, found 3";
    QTest::newRow("position element text") << withBalls(R"([{"id": "cue", "position": [0.6, "0.6"]}])")
                                           << "balls[0].position[1]" << "expected a number";
    QTest::newRow("position an object") << withBalls(R"([{"id": "cue", "position": {"x": 0.6, "y": 0.6}}])")
                                        << "balls[0].position" << "an array of 2 numbers";
    QTest::newRow("velocity one number") << withBalls(R"([{"id": "cue", "position": [0.6, 0.6], "velocity": [1]}])")
                                         << "balls[0].velocity" << "expected 2 numbers, found 1";
    QTest::newRow("spin two numbers") << withBalls(R"([{"id": "cue", "position": [0.6, 0.6], "spin": [1, 2]}])")
                                      << "balls[0].spin" << "expected 3 numbers, found 2";
    QTest::newRow("spin element null") << withBalls(R"([{"id": "cue", "position": [0.6, 0.6], "spin": [0, null, 0]}])")
                                       << "balls[0].spin[1]" << "found null";
    QTest::newRow("radius zero") << withBalls(R"([{"id": "cue", "position": [0.6, 0.6], "radius": 0}])")
                                 << "balls[0].radius" << "greater than 0";
    QTest::newRow("radius negative") << withBalls(R"([{"id": "cue", "position": [0.6, 0.6], "radius": -0.03}])")
                                     << "balls[0].radius" << "greater than 0";
    QTest::newRow("mass zero") << withBalls(R"([{"id": "cue", "position": [0.6, 0.6], "mass": 0}])")
                               << "balls[0].mass" << "greater than 0";
    QTest::newRow("left of the table") << withBalls(R"([{"id": "cue", "position": [-0.5, 0.6]}])")
                                       << "balls[0].position" << "outside the playing surface";
    QTest::newRow("beyond the top rail") << withBalls(R"([{"id": "cue", "position": [1.0, 1.3]}])")
                                         << "balls[0].position" << "outside the playing surface";
    QTest::newRow("in a corner pocket") << withBalls(R"([{"id": "cue", "position": [0.01, 0.01]}])")
                                        << "balls[0].position" << "lies in pocket \"pocket-bl\"";
    QTest::newRow("into a rail") << withBalls(R"([{"id": "cue", "position": [0.6, 0.02]}])") << "balls[0].position"
                                 << "overlaps cushion \"rail-b-left\"";
    QTest::newRow("into a closed rail")
        << withMembers(R"("table": {"kind": "carom"})", R"([{"id": "cue", "position": [0.02, 0.7]}])")
        << "balls[0].position" << "overlaps cushion \"rail-left\" by";
    {
        // A ball pressed 1 mm into the tip of the side pocket's left jaw on the bottom rail.
        const Table table = makeTable(TableKind::Pool9ft);
        const JawTip* jaw = nullptr;
        for (const JawTip& j : table.jaws)
            if (j.id == "jaw-b-left") jaw = &j;
        QVERIFY(jaw);
        const double reach = jaw->radius + table.ballRadius - 0.001;
        const Vec2 p = jaw->centre + reach * Vec2(0.6, 0.8);
        const QByteArray balls = QStringLiteral(R"([{"id": "cue", "position": [%1, %2]}])")
                                     .arg(p.x(), 0, 'g', 17)
                                     .arg(p.y(), 0, 'g', 17)
                                     .toUtf8();
        QTest::newRow("into a jaw tip") << withBalls(balls.constData()) << "balls[0].position"
                                        << "overlaps jaw \"jaw-b-left\" by 1.0 mm";
    }
    QTest::newRow("overlapping balls") << withBalls(R"([{"id": "7", "position": [1.0, 0.6]},
                                                        {"id": "cue", "position": [1.0550499, 0.6]}])")
                                       << "balls[1].position" << "overlaps ball \"7\" by 2.1 mm";
    QTest::newRow("overlap just beyond tolerance") << withBalls(R"([{"id": "7", "position": [1.0, 0.6]},
                                                                    {"id": "cue", "position": [1.057149998, 0.6]}])")
                                                   << "balls[1].position" << "overlaps ball \"7\" by 2.0 nm";

    // shot
    QTest::newRow("shot not an object") << withMembers(R"("shot": "cue")") << "shot" << "expected an object";
    QTest::newRow("shot unknown key") << withShot(R"({"ball": "cue", "sped": 2})") << "shot.sped" << "unknown key";
    QTest::newRow("shot ball missing") << withShot(R"({"speed": 2, "heading": 0, "elevation": 0, "side": 0, "height": 0})")
                                       << "shot.ball" << "missing";
    QTest::newRow("shot names no ball") << withShot(R"({"ball": "9", "speed": 2, "heading": 0, "elevation": 0, "side": 0, "height": 0})")
                                        << "shot.ball" << "there is no ball \"9\"";
    QTest::newRow("shot speed missing") << withShot(R"({"ball": "cue", "heading": 0, "elevation": 0, "side": 0, "height": 0})")
                                        << "shot.speed" << "missing";
    QTest::newRow("shot speed negative") << withShot(R"({"ball": "cue", "speed": -2, "heading": 0, "elevation": 0, "side": 0, "height": 0})")
                                         << "shot.speed" << "must not be negative";
    QTest::newRow("shot heading text") << withShot(R"({"ball": "cue", "speed": 2, "heading": "north", "elevation": 0, "side": 0, "height": 0})")
                                       << "shot.heading" << "expected a number";
    QTest::newRow("shot elevation above 90") << withShot(R"({"ball": "cue", "speed": 2, "heading": 0, "elevation": 95, "side": 0, "height": 0})")
                                             << "shot.elevation" << "between 0 and 90";
    QTest::newRow("shot elevation negative") << withShot(R"({"ball": "cue", "speed": 2, "heading": 0, "elevation": -5, "side": 0, "height": 0})")
                                             << "shot.elevation" << "between 0 and 90";
    QTest::newRow("shot tip misses, side") << withShot(R"({"ball": "cue", "speed": 2, "heading": 0, "elevation": 0, "side": 0.9, "height": 0.5})")
                                           << "shot.side" << "the tip misses the ball";
    QTest::newRow("shot tip misses, height") << withShot(R"({"ball": "cue", "speed": 2, "heading": 0, "elevation": 0, "side": 0, "height": -1})")
                                             << "shot.height" << "the tip misses the ball";
    QTest::newRow("shot cue mass zero") << withShot((QByteArray(kShot) + R"(, "cue_mass": 0})").constData())
                                        << "shot.cue_mass" << "greater than 0";

    // finite but absurd: the safe upper bounds (docs/setup-format.md, "Upper bounds")
    QTest::newRow("shot speed 1e300") << withShot(R"({"ball": "cue", "speed": 1e300, "heading": 0, "elevation": 0, "side": 0, "height": 0})")
                                      << "shot.speed" << "must be at most 1000 m/s (found 1e+300 m/s)";
    QTest::newRow("shot heading 1e300") << withShot(R"({"ball": "cue", "speed": 2, "heading": 1e300, "elevation": 0, "side": 0, "height": 0})")
                                        << "shot.heading" << "between -1e+06 and 1e+06 degrees";
    QTest::newRow("shot cue mass 1e300") << withShot((QByteArray(kShot) + R"(, "cue_mass": 1e300})").constData())
                                         << "shot.cue_mass" << "at most 1e+06 kg";
    QTest::newRow("ball velocity 1e300") << withBalls(R"([{"id": "cue", "position": [0.6, 0.6], "velocity": [1e300, 0]}])")
                                         << "balls[0].velocity" << "ball \"cue\": velocity must be at most 1000 m/s (found 1e+300 m/s)";
    QTest::newRow("ball spin 1e300") << withBalls(R"([{"id": "cue", "position": [0.6, 0.6]}, {"id": "1", "position": [1.8, 0.6], "spin": [0, 1e300, 0]}])")
                                     << "balls[1].spin" << "ball \"1\": spin must be at most 100000 rad/s";
    QTest::newRow("ball position 1e300") << withBalls(R"([{"id": "cue", "position": [1e300, 0.6]}])")
                                         << "balls[0].position" << "outside the playing surface";
    QTest::newRow("ball mass 1e300") << withBalls(R"([{"id": "cue", "position": [0.6, 0.6], "mass": 1e300}])")
                                     << "balls[0].mass" << "at most 1e+06 kg";
    QTest::newRow("table length 1e300") << withMembers(R"("table": {"length": 1e300})") << "table.length" << "at most 1000 m";
    QTest::newRow("gravity 1e300") << withMembers(R"("physics": {"gravity": 1e300})") << "physics.gravity" << "at most 10000";
    QTest::newRow("mu_slide 1e300") << withMembers(R"("physics": {"mu_slide": 1e300})") << "physics.mu_slide" << "at most 1000";
    QTest::newRow("max_time 1e300") << withMembers(R"("simulation": {"max_time": 1e300})") << "simulation.max_time"
                                    << "at most 1e+06 s";

    // simulation
    QTest::newRow("simulation unknown key") << withMembers(R"("simulation": {"frame_rate": 60})")
                                            << "simulation.frame_rate" << "unknown key";
    QTest::newRow("frame_dt zero") << withMembers(R"("simulation": {"frame_dt": 0})") << "simulation.frame_dt"
                                   << "greater than 0";
    QTest::newRow("frame_dt negative") << withMembers(R"("simulation": {"frame_dt": -0.01})") << "simulation.frame_dt"
                                       << "greater than 0";
    QTest::newRow("max_time negative") << withMembers(R"("simulation": {"max_time": -1})") << "simulation.max_time"
                                       << "greater than 0";
    QTest::newRow("max_time text") << withMembers(R"("simulation": {"max_time": "forever"})") << "simulation.max_time"
                                   << "expected a number";
}

void TestSetupRefusals::refused()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, path);
    QFETCH(QString, fragment);
    QString error;
    const std::optional<Setup> setup = io::parseSetup(json, QStringLiteral("rack.json"), &error);
    QVERIFY2(!setup, json.constData());
    const QString prefix = path.isEmpty() ? QStringLiteral("rack.json: ") : QStringLiteral("rack.json: %1: ").arg(path);
    QVERIFY2(error.startsWith(prefix), qPrintable(error));
    QVERIFY2(error.contains(fragment), qPrintable(error));
}

void TestSetupRefusals::notJsonSaysLineAndColumn_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("where");  // Qt's parser reports the place just after the offending token
    QTest::newRow("cut short") << QByteArray(R"({"format": )") << "line 1, column 12";
    QTest::newRow("stray word") << QByteArray("{\n  \"format\": \"cuelab-setup\",\n  x\n}") << "line 3, column 4";
    QTest::newRow("columns count characters") << QByteArray("{\"name\": \"Bälle\", ]") << "line 1, column 20";
    QTest::newRow("number too large") << QByteArray("{\"format\": \"cuelab-setup\",\n \"version\": 1e400}")
                                      << "line 2, column 18";
    QTest::newRow("NaN is not JSON") << QByteArray("{\"version\": NaN}") << "line 1, column 13";
    QTest::newRow("empty file") << QByteArray() << "line 1, column 1";
}

void TestSetupRefusals::notJsonSaysLineAndColumn()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, where);
    QString error;
    QVERIFY(!io::parseSetup(json, QStringLiteral("broken.json"), &error));
    QVERIFY2(error.startsWith(QStringLiteral("broken.json: ") + where + QStringLiteral(": not valid JSON")),
             qPrintable(error));
}

void TestSetupRefusals::overlapAmountIsReadable()
{
    QCOMPARE(io::describeLength(0.0021), QStringLiteral("2.1 mm"));
    QCOMPARE(io::describeLength(3.5e-5), QStringLiteral("35.0 µm"));
    QCOMPARE(io::describeLength(2e-9), QStringLiteral("2.0 nm"));
    QCOMPARE(io::describeLength(0.25), QStringLiteral("0.250 m"));
}

void TestSetupRefusals::validBaseLoads()
{
    // Equal keys in different objects, and keys inside strings, are no duplicates.
    const char* const sameKeysApart = "\"name\": \"{\\\"name\\\": 1, \\\"name\\\": 2}\", "
                                      "\"physics\": {\"ball_ball\": {\"model\": \"frictional\"}, "
                                      "\"ball_cushion\": {\"model\": \"mirror\"}}";
    QString error;
    QVERIFY2(io::parseSetup(withMembers(sameKeysApart), QStringLiteral("rack.json"), &error), qPrintable(error));
    // The documents the rows above break are valid before they are broken.
    QVERIFY2(io::parseSetup(withMembers(""), QStringLiteral("rack.json"), &error), qPrintable(error));
    QVERIFY2(io::parseSetup(withShot((QByteArray(kShot) + "}").constData()), QStringLiteral("rack.json"), &error),
             qPrintable(error));
}

void TestSetupRefusals::nullErrorPointerIsAllowed()
{
    QVERIFY(!io::parseSetup(QByteArray("[]"), QStringLiteral("rack.json"), nullptr));
    QVERIFY(!io::parseSetup(QByteArray("{"), QStringLiteral("rack.json"), nullptr));
}

QTEST_GUILESS_MAIN(TestSetupRefusals)
#include "tst_setuprefusals.moc"
