// serializeSetup: Setup -> JSON text in CONTRACT.md's key order. Numbers print with the shortest
// text that reads back to the same double, so a saved setup loads bit-identical (except that a
// negative zero reads back as zero: Qt's JSON parser drops the sign of "-0").

#include "JsonText.h"
#include "SetupFile.h"
#include "resolve/CushionModel.h"
#include "resolve/TableModel.h"

#include <bit>
#include <cstdint>

namespace cuelab::io {

namespace {

using Layout = JsonWriter::Layout;

bool isPlusZero(double x) { return std::bit_cast<std::uint64_t>(x) == 0; }
bool sameBits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

void writeTable(JsonWriter& w, const TableSpec& spec)
{
    w.key("table");
    w.beginObject(Layout::Line);
    w.key("kind");
    w.value(toString(spec.kind));
    if (spec.length) {
        w.key("length");
        w.value(*spec.length);
    }
    if (spec.width) {
        w.key("width");
        w.value(*spec.width);
    }
    if (spec.cushionHeight) {
        w.key("cushion_height");
        w.value(*spec.cushionHeight);
    }
    w.key("pockets");
    w.value(spec.pockets);
    w.endObject();
}

// Every physics value is written, defaults included: a shared file must reproduce the same shot
// even if a later CueLab changes its defaults.
void writePhysics(JsonWriter& w, const PhysicsParams& p)
{
    w.key("physics");
    w.beginObject(Layout::Block);
    w.key("gravity");
    w.value(p.gravity);
    w.key("mu_slide");
    w.value(p.muSlide);
    w.key("mu_roll");
    w.value(p.muRoll);
    w.key("mu_spin");
    w.value(p.muSpin);
    w.key("ball_ball");
    w.beginObject(Layout::Line);
    w.key("model");
    w.value(toString(p.ballBallModel));
    w.key("restitution");
    w.value(p.ballBallRestitution);
    w.key("friction");
    // The file holds either the fit's name or a fixed coefficient, so with the fit the (unused)
    // fixed coefficient is not saved and reads back as its default.
    if (p.ballBallFrictionKind == BallBallFriction::Alciatore)
        w.value("alciatore");
    else
        w.value(p.ballBallFriction);
    w.endObject();
    w.key("ball_cushion");
    w.beginObject(Layout::Line);
    w.key("model");
    w.value(toString(p.ballCushionModel));
    w.key("restitution");
    w.value(p.cushionRestitution);
    w.key("friction");
    w.value(p.cushionFriction);
    // The chosen model's own parameters (the parser refuses those of another model).
    for (const CushionModelParameter& q : cushionModel(p.ballCushionModel).parameters) {
        w.key(q.key);
        w.value(p.*(q.field));
    }
    w.endObject();
    // The ball-table impact only matters once a ball flies; written when it differs from the
    // defaults, so that the file of a shot on the cloth stays what it was before balls could fly.
    const PhysicsParams d;
    if (p.ballTableModel != d.ballTableModel || !sameBits(p.tableRestitution, d.tableRestitution)
        || !sameBits(p.tableFriction, d.tableFriction)) {
        w.key("ball_table");
        w.beginObject(Layout::Line);
        if (p.ballTableModel != d.ballTableModel) {
            w.key("model");
            w.value(toString(p.ballTableModel));
        }
        w.key("restitution");
        w.value(p.tableRestitution);
        w.key("friction");
        w.value(p.tableFriction);
        w.endObject();
    }
    w.endObject();
}

// Optional ball keys are left out when they hold their default (zero motion, the table's ball).
void writeBall(JsonWriter& w, const Ball& ball, const Table& table)
{
    const BallState& s = ball.state;
    w.beginObject(Layout::Line);
    w.key("id");
    w.value(ball.id);
    w.key("position");
    w.numbers(s.position.data(), 2);
    if (!isPlusZero(s.velocity.x()) || !isPlusZero(s.velocity.y())) {
        w.key("velocity");
        w.numbers(s.velocity.data(), 2);
    }
    if (!isPlusZero(s.spin.x()) || !isPlusZero(s.spin.y()) || !isPlusZero(s.spin.z())) {
        w.key("spin");
        w.numbers(s.spin.data(), 3);
    }
    if (!isPlusZero(s.z)) {
        w.key("z");
        w.value(s.z);
    }
    if (!isPlusZero(s.vz)) {
        w.key("vz");
        w.value(s.vz);
    }
    if (!sameBits(ball.radius, table.ballRadius)) {
        w.key("radius");
        w.value(ball.radius);
    }
    if (!sameBits(ball.mass, table.ballMass)) {
        w.key("mass");
        w.value(ball.mass);
    }
    w.endObject();
}

void writeShot(JsonWriter& w, const CueStrike& shot)
{
    w.key("shot");
    w.beginObject(Layout::Line);
    w.key("ball");
    w.value(shot.ball);
    w.key("speed");
    w.value(shot.speed);
    w.key("heading");
    w.value(shot.headingDeg);
    w.key("elevation");
    w.value(shot.elevationDeg);
    w.key("side");
    w.value(shot.side);
    w.key("height");
    w.value(shot.height);
    w.key("cue_mass");
    w.value(shot.cueMass);
    if (shot.endMass > 0.0) {  // absent = no squirt
        w.key("end_mass");
        w.value(shot.endMass);
    }
    w.endObject();
}

// The lesson's questions and the setup its notes were written for, only when there are any (a file
// without them stays as it was).
void writeLesson(JsonWriter& w, const std::vector<PredictQuestion>& questions, const std::string& notesWrittenFor)
{
    w.key("lesson");
    w.beginObject(Layout::Block);
    if (!notesWrittenFor.empty()) {
        w.key("notes_written_for");
        w.value(notesWrittenFor);
    }
    if (questions.empty()) {
        w.endObject();
        return;
    }
    w.key("questions");
    w.beginArray(Layout::Block);
    for (const PredictQuestion& q : questions) {
        w.beginObject(Layout::Line);
        if (q.event) {
            w.key("event");
            w.value(*q.event);
        }
        if (!q.balls.empty()) {
            w.key("balls");
            w.beginArray(Layout::Line);
            for (const std::string& id : q.balls) w.value(id);
            w.endArray();
        }
        if (!q.prompt.empty()) {
            w.key("prompt");
            w.value(q.prompt);
        }
        w.endObject();
    }
    w.endArray();
    w.endObject();
}

// The game, only when there is one (a file without it stays as it was); optional keys only when set.
void writeGame(JsonWriter& w, const GameSpec& game)
{
    w.key("game");
    w.beginObject(Layout::Line);
    w.key("rules");
    w.value(std::string(toString(game.rules)));
    if (game.group) {
        w.key("group");
        w.value(std::string(toString(*game.group)));
    }
    if (game.on) {
        w.key("on");
        w.value(std::string(toString(*game.on)));
    }
    if (!game.nominated.empty()) {
        w.key("nominated");
        w.value(game.nominated);
    }
    if (game.breakShot) {
        w.key("break");
        w.value(true);
    }
    w.endObject();
}

}  // namespace

QByteArray serializeSetup(const Setup& setup)
{
    JsonWriter w;
    w.beginObject(Layout::Block);
    w.key("format");
    w.value("cuelab-setup");
    w.key("version");
    w.value(1);
    if (!setup.name.empty()) {
        w.key("name");
        w.value(setup.name);
    }
    if (!setup.notes.empty()) {
        w.key("notes");
        w.value(setup.notes);
    }
    if (!setup.questions.empty() || !setup.notesWrittenFor.empty()) writeLesson(w, setup.questions, setup.notesWrittenFor);
    writeTable(w, setup.table);
    writePhysics(w, setup.physics);
    w.key("balls");
    w.beginArray(Layout::Block);
    const Table table = makeTable(setup.table);
    for (const Ball& ball : setup.balls) writeBall(w, ball, table);
    w.endArray();
    if (setup.shot) writeShot(w, *setup.shot);
    if (setup.game) writeGame(w, *setup.game);
    w.key("simulation");
    w.beginObject(Layout::Line);
    w.key("frame_dt");
    w.value(setup.simulation.frameDt);
    w.key("max_time");
    w.value(setup.simulation.maxTime);
    w.endObject();
    w.endObject();
    return QByteArray::fromStdString(w.text());
}

}  // namespace cuelab::io
