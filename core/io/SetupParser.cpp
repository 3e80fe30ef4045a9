// parseSetup: JSON text -> Setup, refusing (never half-loading) anything CONTRACT.md version 1 does
// not allow or the simulator cannot take. Every refusal names the JSON path of the culprit.
// This file reads the document's shape (keys, types, names of kinds and models); whether the values
// make a legal setup is the Qt-free validator's to say (core/setup, LegalSetup.h), whose messages
// are only formatted here.

#include "JsonDuplicateKeys.h"
#include "KindDefaults.h"
#include "LegalSetup.h"
#include "SetupFile.h"
#include "ShotCode.h"
#include "SetupProblem.h"
#include "resolve/CushionModel.h"
#include "resolve/TableModel.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

namespace cuelab::io {

namespace {

// Thrown at the first problem and caught in parseSetup, so that the parsing code reads top-down.
struct Refusal {
    SetupProblem problem;
};

[[noreturn]] void refuse(const QString& path, const QString& message) { throw Refusal{{path, message}}; }

QString child(const QString& path, const char* key)
{
    return path.isEmpty() ? QLatin1String(key) : path + QLatin1Char('.') + QLatin1String(key);
}

QString element(const QString& path, qsizetype index) { return path + QStringLiteral("[%1]").arg(index); }

QString describe(const QJsonValue& v)
{
    switch (v.type()) {
    case QJsonValue::Null: return QStringLiteral("null");
    case QJsonValue::Bool: return QStringLiteral("true/false");
    case QJsonValue::Double: return QStringLiteral("a number");
    case QJsonValue::String: return QStringLiteral("a string");
    case QJsonValue::Array: return QStringLiteral("an array");
    case QJsonValue::Object: return QStringLiteral("an object");
    case QJsonValue::Undefined: break;
    }
    return QStringLiteral("nothing");
}

[[noreturn]] void wrongType(const QString& path, const char* expected, const QJsonValue& found)
{
    refuse(path, QStringLiteral("expected %1, found %2").arg(QLatin1String(expected), describe(found)));
}

// An object with its path. Reading a key that is absent yields nullopt for optional keys and a
// refusal for required ones; keys not in `allowed` are refused (typos must not pass silently).
class ObjectReader {
public:
    ObjectReader(const QJsonValue& value, QString path, std::initializer_list<const char*> allowed)
        : ObjectReader(value, std::move(path), std::vector<const char*>(allowed))
    {
    }
    ObjectReader(const QJsonValue& value, QString path, const std::vector<const char*>& allowed)
        : path_(std::move(path))
    {
        if (!value.isObject()) wrongType(path_, "an object", value);
        object_ = value.toObject();
        for (auto it = object_.begin(); it != object_.end(); ++it) {
            bool known = false;
            for (const char* key : allowed) known = known || it.key() == QLatin1String(key);
            if (!known) {
                QStringList names;
                for (const char* key : allowed) names << QLatin1String(key);
                refuse(child(path_, it.key().toUtf8().constData()),
                       QStringLiteral("unknown key (expected one of: %1)").arg(names.join(QStringLiteral(", "))));
            }
        }
    }

    const QString& path() const { return path_; }
    QString pathOf(const char* key) const { return child(path_, key); }
    bool has(const char* key) const { return object_.contains(QLatin1String(key)); }

    QJsonValue required(const char* key) const
    {
        if (!has(key)) refuse(pathOf(key), QStringLiteral("required key is missing"));
        return object_.value(QLatin1String(key));
    }
    QJsonValue value(const char* key) const { return object_.value(QLatin1String(key)); }

    double number(const char* key) const { return toNumber(required(key), pathOf(key)); }
    std::optional<double> optionalNumber(const char* key) const
    {
        if (!has(key)) return std::nullopt;
        return toNumber(value(key), pathOf(key));
    }
    QString string(const char* key) const
    {
        const QJsonValue v = required(key);
        if (!v.isString()) wrongType(pathOf(key), "a string", v);
        return v.toString();
    }
    std::optional<QString> optionalString(const char* key) const
    {
        if (!has(key)) return std::nullopt;
        return string(key);
    }
    std::optional<bool> optionalBool(const char* key) const
    {
        if (!has(key)) return std::nullopt;
        const QJsonValue v = value(key);
        if (!v.isBool()) wrongType(pathOf(key), "true or false", v);
        return v.toBool();
    }

    static double toNumber(const QJsonValue& v, const QString& path)
    {
        if (!v.isDouble()) wrongType(path, "a number", v);
        const double x = v.toDouble();
        // Qt's parser already refuses numbers that overflow a double; this guards the contract anyway.
        if (!std::isfinite(x)) refuse(path, QStringLiteral("the number is not finite"));
        return x;
    }

private:
    QString path_;
    QJsonObject object_;
};

template <int N>
Eigen::Matrix<double, N, 1> vector(const QJsonValue& v, const QString& path)
{
    if (!v.isArray()) wrongType(path, N == 2 ? "an array of 2 numbers" : "an array of 3 numbers", v);
    const QJsonArray array = v.toArray();
    if (array.size() != N)
        refuse(path, QStringLiteral("expected %1 numbers, found %2").arg(N).arg(array.size()));
    Eigen::Matrix<double, N, 1> out;
    for (int i = 0; i < N; ++i) out[i] = ObjectReader::toNumber(array[i], element(path, i));
    return out;
}

// The header is read before anything else, so that another kind of JSON file is refused as such,
// not for its keys.
void checkHeader(const QJsonObject& root)
{
    const QJsonValue format = root.value(QLatin1String("format"));
    if (format.isUndefined())
        refuse(QStringLiteral("format"), QStringLiteral("required key is missing (not a CueLab setup file?)"));
    if (!format.isString()) wrongType(QStringLiteral("format"), "a string", format);
    if (format.toString() != QLatin1String("cuelab-setup"))
        refuse(QStringLiteral("format"), QStringLiteral("expected \"cuelab-setup\", found \"%1\"").arg(format.toString()));
    const QJsonValue version = root.value(QLatin1String("version"));
    if (version.isUndefined()) refuse(QStringLiteral("version"), QStringLiteral("required key is missing"));
    const double number = ObjectReader::toNumber(version, QStringLiteral("version"));
    if (number != 1.0)
        refuse(QStringLiteral("version"),
               QStringLiteral("version %1 is not supported (this CueLab reads version 1)").arg(number));
}

TableSpec parseTable(const QJsonValue& value)
{
    const ObjectReader in(value, QStringLiteral("table"), {"kind", "length", "width", "cushion_height", "pockets"});
    TableSpec spec;
    if (const auto kind = in.optionalString("kind")) {
        if (!parseTableKind(kind->toStdString(), spec.kind))
            refuse(in.pathOf("kind"),
                   QStringLiteral("unknown table kind \"%1\" (expected pool-9ft, pool-8ft, pool-7ft, snooker or carom)")
                       .arg(*kind));
    }
    spec.length = in.optionalNumber("length");
    spec.width = in.optionalNumber("width");
    spec.cushionHeight = in.optionalNumber("cushion_height");
    if (const auto pockets = in.optionalBool("pockets")) spec.pockets = *pockets;
    return spec;
}

void parseBallBall(const QJsonValue& value, const QString& path, PhysicsParams& p)
{
    const ObjectReader in(value, path, {"model", "restitution", "friction"});
    if (const auto model = in.optionalString("model")) {
        if (*model == QLatin1String("frictionless"))
            p.ballBallModel = BallBallModel::Frictionless;
        else if (*model == QLatin1String("frictional"))
            p.ballBallModel = BallBallModel::Frictional;
        else
            refuse(in.pathOf("model"),
                   QStringLiteral("unknown model \"%1\" (expected frictionless or frictional)").arg(*model));
    }
    if (const auto e = in.optionalNumber("restitution")) p.ballBallRestitution = *e;
    if (in.has("friction")) {
        const QJsonValue friction = in.value("friction");
        if (friction.isString()) {
            if (friction.toString() != QLatin1String("alciatore"))
                refuse(in.pathOf("friction"),
                       QStringLiteral("expected a number or \"alciatore\", found \"%1\"").arg(friction.toString()));
            p.ballBallFrictionKind = BallBallFriction::Alciatore;
        } else if (friction.isDouble()) {
            p.ballBallFrictionKind = BallBallFriction::Fixed;
            p.ballBallFriction = ObjectReader::toNumber(friction, in.pathOf("friction"));
        } else {
            wrongType(in.pathOf("friction"), "a number or \"alciatore\"", friction);
        }
    }
}

// The models, their names and their own parameters come from the registry (resolve/CushionModel.h);
// a parameter of another model than the one chosen is refused as an unknown key.
void parseBallCushion(const QJsonValue& value, const QString& path, PhysicsParams& p)
{
    if (!value.isObject()) wrongType(path, "an object", value);
    const QJsonObject object = value.toObject();
    const CushionModelEntry* model = &cushionModel(p.ballCushionModel);
    if (object.contains(QLatin1String("model"))) {
        const QJsonValue v = object.value(QLatin1String("model"));
        if (!v.isString()) wrongType(child(path, "model"), "a string", v);
        model = findCushionModel(v.toString().toStdString());
        if (!model) {
            QStringList names;
            for (const CushionModelEntry& e : cushionModels()) names << QString::fromUtf8(e.name.data(), qsizetype(e.name.size()));
            refuse(child(path, "model"), QStringLiteral("unknown model \"%1\" (expected one of: %2)")
                                             .arg(v.toString(), names.join(QStringLiteral(", "))));
        }
        p.ballCushionModel = model->model;
    }
    // The model's own parameters are read here; their ranges are the validator's (core/setup).
    std::vector<std::string> keys{"model", "restitution", "friction"};
    for (const CushionModelParameter& q : model->parameters) keys.emplace_back(q.key);
    std::vector<const char*> allowed;
    for (const std::string& k : keys) allowed.push_back(k.c_str());
    const ObjectReader in(value, path, allowed);
    if (const auto e = in.optionalNumber("restitution")) p.cushionRestitution = *e;
    if (const auto mu = in.optionalNumber("friction")) p.cushionFriction = *mu;
    for (const CushionModelParameter& q : model->parameters) {
        const std::string key(q.key);
        if (const auto x = in.optionalNumber(key.c_str())) p.*(q.field) = *x;
    }
}

// CONTRACT.md "Airborne balls": physics.ball_table {restitution, friction} (optional), and a model
// by the registry's name (resolve/TableModel.h), an additive key.
void parseBallTable(const QJsonValue& value, const QString& path, PhysicsParams& p)
{
    const ObjectReader in(value, path, {"model", "restitution", "friction"});
    if (in.has("model")) {
        const QJsonValue v = in.value("model");
        if (!v.isString()) wrongType(child(path, "model"), "a string", v);
        const TableModelEntry* model = findTableModel(v.toString().toStdString());
        if (!model) {
            QStringList names;
            for (const TableModelEntry& e : tableModels()) names << QString::fromUtf8(e.name.data(), qsizetype(e.name.size()));
            refuse(child(path, "model"), QStringLiteral("unknown model \"%1\" (expected one of: %2)")
                                             .arg(v.toString(), names.join(QStringLiteral(", "))));
        }
        p.ballTableModel = model->model;
    }
    if (const auto e = in.optionalNumber("restitution")) p.tableRestitution = *e;
    if (const auto mu = in.optionalNumber("friction")) p.tableFriction = *mu;
}

// A key left out takes the table kind's default (`defaults`: KindDefaults.h).
PhysicsParams parsePhysics(const QJsonValue& value, const PhysicsParams& defaults)
{
    const ObjectReader in(value, QStringLiteral("physics"),
                          {"gravity", "mu_slide", "mu_roll", "mu_spin", "ball_ball", "ball_cushion", "ball_table"});
    PhysicsParams p = defaults;
    if (const auto g = in.optionalNumber("gravity")) p.gravity = *g;
    if (const auto mu = in.optionalNumber("mu_slide")) p.muSlide = *mu;
    if (const auto mu = in.optionalNumber("mu_roll")) p.muRoll = *mu;
    if (const auto mu = in.optionalNumber("mu_spin")) p.muSpin = *mu;
    if (in.has("ball_ball")) parseBallBall(in.value("ball_ball"), in.pathOf("ball_ball"), p);
    if (in.has("ball_cushion")) parseBallCushion(in.value("ball_cushion"), in.pathOf("ball_cushion"), p);
    if (in.has("ball_table")) parseBallTable(in.value("ball_table"), in.pathOf("ball_table"), p);
    return p;
}

// `preset` gives the radius and mass of a ball that states none (the table kind's balls).
std::vector<Ball> parseBalls(const QJsonValue& value, const Table& preset)
{
    const QString path = QStringLiteral("balls");
    if (!value.isArray()) wrongType(path, "an array", value);
    const QJsonArray array = value.toArray();
    std::vector<Ball> balls;
    for (qsizetype i = 0; i < array.size(); ++i) {
        const ObjectReader in(array[i], element(path, i), {"id", "position", "velocity", "spin", "radius", "mass", "z", "vz"});
        Ball ball;
        ball.id = in.string("id").toStdString();
        ball.state.position = vector<2>(in.required("position"), in.pathOf("position"));
        if (in.has("velocity")) ball.state.velocity = vector<2>(in.value("velocity"), in.pathOf("velocity"));
        if (in.has("spin")) ball.state.spin = vector<3>(in.value("spin"), in.pathOf("spin"));
        // A ball may start in the air (CONTRACT.md "Airborne balls"); the validator refuses z < 0.
        if (const auto z = in.optionalNumber("z")) ball.state.z = *z;
        if (const auto vz = in.optionalNumber("vz")) ball.state.vz = *vz;
        ball.radius = in.optionalNumber("radius").value_or(preset.ballRadius);
        ball.mass = in.optionalNumber("mass").value_or(preset.ballMass);
        ball.state.motion = classify(ball.state, ball.radius);
        balls.push_back(std::move(ball));
    }
    return balls;
}

CueStrike parseShot(const QJsonValue& value)
{
    const ObjectReader in(value, QStringLiteral("shot"),
                          {"ball", "speed", "heading", "elevation", "side", "height", "cue_mass", "end_mass"});
    CueStrike shot;
    shot.ball = in.string("ball").toStdString();
    shot.speed = in.number("speed");
    shot.headingDeg = in.number("heading");
    shot.elevationDeg = in.number("elevation");
    shot.side = in.number("side");
    shot.height = in.number("height");
    if (const auto m = in.optionalNumber("cue_mass")) shot.cueMass = *m;
    // Squirt only when the file asks for it with the tip's end mass (Alciatore TP A-31).
    if (const auto m = in.optionalNumber("end_mass")) shot.endMass = *m;
    return shot;
}

SimulationSettings parseSimulation(const QJsonValue& value)
{
    const ObjectReader in(value, QStringLiteral("simulation"), {"frame_dt", "max_time"});
    SimulationSettings s;
    if (const auto dt = in.optionalNumber("frame_dt")) s.frameDt = *dt;
    if (const auto t = in.optionalNumber("max_time")) s.maxTime = *t;
    return s;
}

// "lesson": {"questions": [{"event": 3, "balls": ["cue", "1"], "prompt": "..."}]} (issue 22: predict,
// then reveal). Each question is refused as a whole for a wrong shape; a ball it names must be one of
// the setup's, so that a teacher's typo does not silently drop a ball from the question.
// "notes_written_for": the shot code of the setup the notes were written for (a code that does not
// decode is refused, naming its problem).
std::string parseNotesWrittenFor(const ObjectReader& in)
{
    if (!in.has("notes_written_for")) return {};
    const QJsonValue v = in.value("notes_written_for");
    if (!v.isString()) wrongType(in.pathOf("notes_written_for"), "a shot code (a string)", v);
    QString problem;
    if (!parseShotCode(v.toString(), &problem))
        refuse(in.pathOf("notes_written_for"), QStringLiteral("not a shot code CueLab can read: %1").arg(problem));
    return v.toString().toStdString();
}

std::vector<PredictQuestion> parseLesson(const QJsonValue& value, const std::vector<Ball>& balls, std::string* notesWrittenFor)
{
    const ObjectReader in(value, QStringLiteral("lesson"), {"questions", "notes_written_for"});
    *notesWrittenFor = parseNotesWrittenFor(in);
    std::vector<PredictQuestion> questions;
    if (!in.has("questions")) return questions;
    const QString path = in.pathOf("questions");
    const QJsonValue list = in.value("questions");
    if (!list.isArray()) wrongType(path, "an array", list);
    const QJsonArray array = list.toArray();
    for (qsizetype i = 0; i < array.size(); ++i) {
        const ObjectReader q(array[i], element(path, i), {"event", "balls", "prompt"});
        PredictQuestion question;
        if (const auto event = q.optionalNumber("event")) {
            if (*event < 0 || *event != std::floor(*event) || *event > 1e9)
                refuse(q.pathOf("event"), QStringLiteral("expected a whole number >= 0 (the 0-based index of an event), "
                                                         "found %1").arg(*event));
            question.event = static_cast<int>(*event);
        }
        if (q.has("balls")) {
            const QJsonValue ids = q.value("balls");
            if (!ids.isArray()) wrongType(q.pathOf("balls"), "an array of ball ids", ids);
            const QJsonArray idArray = ids.toArray();
            for (qsizetype k = 0; k < idArray.size(); ++k) {
                const QString at = element(q.pathOf("balls"), k);
                if (!idArray[k].isString()) wrongType(at, "a ball id (a string)", idArray[k]);
                const std::string id = idArray[k].toString().toStdString();
                if (std::none_of(balls.begin(), balls.end(), [&id](const Ball& b) { return b.id == id; }))
                    refuse(at, QStringLiteral("no ball \"%1\" in the setup").arg(idArray[k].toString()));
                if (std::find(question.balls.begin(), question.balls.end(), id) != question.balls.end())
                    refuse(at, QStringLiteral("ball \"%1\" is named twice").arg(idArray[k].toString()));
                question.balls.push_back(id);
            }
        }
        question.prompt = q.optionalString("prompt").value_or(QString()).toStdString();
        questions.push_back(std::move(question));
    }
    return questions;
}

// "game": {"rules": "9-ball", "group": "open", "on": "red", "nominated": "pocket-tr", "break": true}
// (CONTRACT.md, Extensions version 3). The names only; whether the balls fit the game is the
// validator's (core/setup, LegalGame.h).
GameSpec parseGame(const QJsonValue& value)
{
    const ObjectReader in(value, QStringLiteral("game"), {"rules", "group", "on", "nominated", "break"});
    GameSpec game;
    const QString rules = in.string("rules");
    if (!parseGameRules(rules.toStdString(), game.rules))
        refuse(in.pathOf("rules"), QStringLiteral("unknown rules \"%1\" (expected %2)")
                                       .arg(rules, QString::fromStdString(gameRulesNames())));
    if (const auto group = in.optionalString("group")) {
        PoolGroup g{};
        if (!parsePoolGroup(group->toStdString(), g))
            refuse(in.pathOf("group"), QStringLiteral("unknown group \"%1\" (expected %2)")
                                           .arg(*group, QString::fromStdString(poolGroupNames())));
        game.group = g;
    }
    if (const auto on = in.optionalString("on")) {
        SnookerOn o{};
        if (!parseSnookerOn(on->toStdString(), o))
            refuse(in.pathOf("on"), QStringLiteral("unknown ball on \"%1\" (expected %2)")
                                        .arg(*on, QString::fromStdString(snookerOnNames())));
        game.on = o;
    }
    game.nominated = in.optionalString("nominated").value_or(QString()).toStdString();
    game.breakShot = in.optionalBool("break").value_or(false);
    return game;
}

Setup parseDocument(const QJsonValue& document)
{
    if (!document.isObject()) wrongType(QString(), "a JSON object at the top level", document);
    checkHeader(document.toObject());
    const ObjectReader in(document, QString(),
                          {"format", "version", "name", "notes", "lesson", "table", "physics", "balls", "shot", "simulation",
                           "game"});
    Setup setup;
    setup.name = in.optionalString("name").value_or(QString()).toStdString();
    setup.notes = in.optionalString("notes").value_or(QString()).toStdString();
    if (in.has("table")) setup.table = parseTable(in.value("table"));
    // A table kind brings its own cloth: a carom table's keys left out are carom cloth's.
    setup.physics = defaultPhysics(setup.table.kind);
    if (in.has("physics")) setup.physics = parsePhysics(in.value("physics"), setup.physics);
    setup.balls = parseBalls(in.required("balls"), makeTable(setup.table.kind));
    if (in.has("shot")) setup.shot = parseShot(in.value("shot"));
    if (in.has("simulation")) setup.simulation = parseSimulation(in.value("simulation"));
    if (in.has("lesson")) setup.questions = parseLesson(in.value("lesson"), setup.balls, &setup.notesWrittenFor);
    if (in.has("game")) setup.game = parseGame(in.value("game"));
    // The values and the geometry: the one validator's first problem, its message as it is.
    if (const std::optional<cuelab::SetupProblem> problem = firstSetupProblem(setup))
        refuse(QString::fromStdString(problem->path), QString::fromStdString(problem->message));
    return setup;
}

// Line and column (both from 1; the column counts characters, not bytes) of a byte offset.
std::pair<int, int> lineAndColumn(const QByteArray& text, qsizetype offset)
{
    int line = 1, column = 1;
    for (qsizetype i = 0; i < std::min(offset, text.size()); ++i) {
        const char c = text[i];
        if (c == '\n') {
            ++line;
            column = 1;
        } else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {  // not a UTF-8 continuation byte
            ++column;
        }
    }
    return {line, column};
}

}  // namespace

std::optional<Setup> parseSetup(const QByteArray& json, const QString& fileName, QString* error)
{
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        const auto [line, column] = lineAndColumn(json, parseError.offset);
        if (error)
            *error = QStringLiteral("%1: line %2, column %3: not valid JSON (%4)")
                         .arg(fileName)
                         .arg(line)
                         .arg(column)
                         .arg(parseError.errorString());
        return std::nullopt;
    }
    try {
        if (auto duplicate = findDuplicateKey(json)) throw Refusal{*duplicate};
        const QJsonValue root = document.isObject() ? QJsonValue(document.object()) : QJsonValue(document.array());
        return parseDocument(root);
    } catch (const Refusal& refusal) {
        if (error) {
            const SetupProblem& p = refusal.problem;
            *error = p.path.isEmpty() ? QStringLiteral("%1: %2").arg(fileName, p.message)
                                      : QStringLiteral("%1: %2: %3").arg(fileName, p.path, p.message);
        }
        return std::nullopt;
    }
}

}  // namespace cuelab::io
