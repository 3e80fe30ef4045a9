#include "Override.h"

#include "NumberText.h"
#include "resolve/CushionModel.h"

#include <array>
#include <charconv>
#include <cmath>

namespace cuelab::analysis {

enum class Parameter::Field : int {
    ShotBall, ShotSpeed, ShotHeading, ShotElevation, ShotSide, ShotHeight, ShotCueMass, ShotEndMass,
    Gravity, MuSlide, MuRoll, MuSpin,
    BallBallModel, BallBallRestitution, BallBallFriction,
    BallCushionModel, BallCushionRestitution, BallCushionFriction,
    CushionModelParameter,  // a registered model's own parameter (CushionModels.cpp): physics.ball_cushion.<key>
    TableKind, TablePockets, TableLength, TableWidth, TableCushionHeight,
    BallX, BallY, BallVx, BallVy, BallWx, BallWy, BallWz, BallRadius, BallMass,
    MaxTime, FrameDt,
    Name, Notes,
    GameRules, GameGroup, GameOn, GameNominated, GameBreak,
};

namespace {

using Field = Parameter::Field;
using Type = Parameter::Type;

struct KeyInfo {
    const char* name;  // full key, or for ball keys the part after "balls.<id>."
    Field field;
    Type type;
};

// The setup-wide keys, in the order of the setup file.
constexpr std::array kKeys{
    KeyInfo{"shot.ball", Field::ShotBall, Type::Text},
    KeyInfo{"shot.speed", Field::ShotSpeed, Type::Number},
    KeyInfo{"shot.heading", Field::ShotHeading, Type::Number},
    KeyInfo{"shot.elevation", Field::ShotElevation, Type::Number},
    KeyInfo{"shot.side", Field::ShotSide, Type::Number},
    KeyInfo{"shot.height", Field::ShotHeight, Type::Number},
    KeyInfo{"shot.cue_mass", Field::ShotCueMass, Type::Number},
    // 0, like the key absent, is no squirt (docs/setup-format.md).
    KeyInfo{"shot.end_mass", Field::ShotEndMass, Type::Number},
    KeyInfo{"physics.gravity", Field::Gravity, Type::Number},
    KeyInfo{"physics.mu_slide", Field::MuSlide, Type::Number},
    KeyInfo{"physics.mu_roll", Field::MuRoll, Type::Number},
    KeyInfo{"physics.mu_spin", Field::MuSpin, Type::Number},
    KeyInfo{"physics.ball_ball.model", Field::BallBallModel, Type::Text},
    KeyInfo{"physics.ball_ball.restitution", Field::BallBallRestitution, Type::Number},
    // A number, or "alciatore" for the speed-dependent fit; numeric for sweeps.
    KeyInfo{"physics.ball_ball.friction", Field::BallBallFriction, Type::Number},
    KeyInfo{"physics.ball_cushion.model", Field::BallCushionModel, Type::Text},
    KeyInfo{"physics.ball_cushion.restitution", Field::BallCushionRestitution, Type::Number},
    KeyInfo{"physics.ball_cushion.friction", Field::BallCushionFriction, Type::Number},
    // physics.ball_cushion.<key> of the model's own parameters follow here, from the registry.
    KeyInfo{"table.kind", Field::TableKind, Type::Text},
    KeyInfo{"table.pockets", Field::TablePockets, Type::Bool},
    KeyInfo{"table.length", Field::TableLength, Type::Number},
    KeyInfo{"table.width", Field::TableWidth, Type::Number},
    KeyInfo{"table.cushion_height", Field::TableCushionHeight, Type::Number},
    KeyInfo{"simulation.max_time", Field::MaxTime, Type::Number},
    KeyInfo{"simulation.frame_dt", Field::FrameDt, Type::Number},
    KeyInfo{"name", Field::Name, Type::Text},
    KeyInfo{"notes", Field::Notes, Type::Text},
    // The game (CONTRACT.md, Extensions version 3): listed only for a setup that has one, so that the
    // keys of a setup without a game read as before; game.rules sets one up (or "none" takes it away).
    KeyInfo{"game.rules", Field::GameRules, Type::Text},
    KeyInfo{"game.group", Field::GameGroup, Type::Text},
    KeyInfo{"game.on", Field::GameOn, Type::Text},
    KeyInfo{"game.nominated", Field::GameNominated, Type::Text},
    KeyInfo{"game.break", Field::GameBreak, Type::Bool},
};

constexpr std::string_view kCushionPrefix = "physics.ball_cushion.";

// The keys of one ball: balls.<id>.<name>.
constexpr std::array kBallKeys{
    KeyInfo{"x", Field::BallX, Type::Number},          KeyInfo{"y", Field::BallY, Type::Number},
    KeyInfo{"vx", Field::BallVx, Type::Number},        KeyInfo{"vy", Field::BallVy, Type::Number},
    KeyInfo{"wx", Field::BallWx, Type::Number},        KeyInfo{"wy", Field::BallWy, Type::Number},
    KeyInfo{"wz", Field::BallWz, Type::Number},        KeyInfo{"radius", Field::BallRadius, Type::Number},
    KeyInfo{"mass", Field::BallMass, Type::Number},
};

const KeyInfo& infoOf(Field field)
{
    for (const KeyInfo& k : kKeys)
        if (k.field == field) return k;
    for (const KeyInfo& k : kBallKeys)
        if (k.field == field) return k;
    return kKeys[0];
}

bool isShotField(Field f) { return f >= Field::ShotBall && f <= Field::ShotEndMass; }
bool isGameField(Field f) { return f >= Field::GameRules && f <= Field::GameBreak; }

std::string quoted(std::string_view text) { return "\"" + std::string(text) + "\""; }

OverrideError unknownKey(std::string_view key, const std::string& why)
{
    return {OverrideError::Kind::UnknownKey, std::string(key), "unknown key " + quoted(key) + " (" + why + ")"};
}

OverrideError badValue(std::string_view key, std::string_view value, const std::string& expected)
{
    return {OverrideError::Kind::BadValue, std::string(key),
            std::string(key) + ": expected " + expected + ", found " + quoted(value)};
}

std::string joined(const std::vector<std::string>& items, std::string_view separator)
{
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : std::string(separator)) + item;
    return out;
}

// "mirror, han2005, mathavan2010 or stronge": the registry's names (CushionModels.cpp), in its order.
std::string cushionModelNames()
{
    std::vector<std::string> names;
    for (const CushionModelEntry& e : cushionModels()) names.emplace_back(e.name);
    const std::string last = names.back();
    names.pop_back();
    return joined(names, ", ") + " or " + last;
}

// "pool-9ft, pool-8ft, pool-7ft, snooker or carom", from the table kinds themselves.
std::string tableKindNames()
{
    std::vector<std::string> names;
    for (TableKind k : {TableKind::Pool9ft, TableKind::Pool8ft, TableKind::Pool7ft, TableKind::Snooker, TableKind::Carom})
        names.emplace_back(toString(k));
    const std::string last = names.back();
    names.pop_back();
    return joined(names, ", ") + " or " + last;
}

// The registered model that has the parameter `key` ("steps"), and the parameter; nullptrs if none.
std::pair<const CushionModelEntry*, const CushionModelParameter*> findModelParameter(std::string_view key)
{
    for (const CushionModelEntry& e : cushionModels())
        for (const CushionModelParameter& q : e.parameters)
            if (q.key == key) return {&e, &q};
    return {nullptr, nullptr};
}

// The valid keys of `setup`, for an unknown key's message: every setup-wide key, the current model's
// parameters, and the ball keys with the setup's ids.
std::string validKeys(const Setup& setup)
{
    std::vector<std::string> keys;
    for (const std::string& k : overridableKeys(setup, false))
        if (k.rfind("balls.", 0) != 0) keys.push_back(k);
    std::string text = "valid keys: " + joined(keys, ", ");
    if (setup.balls.empty()) return text;
    std::vector<std::string> ids;
    for (const Ball& b : setup.balls) ids.push_back(b.id);
    return text + ", balls.<id>.x|y|vx|vy|wx|wy|wz|radius|mass with <id> one of " + joined(ids, ", ");
}

std::string numberText(double x) { return roundTripText(x); }

// The motion label must agree with the numbers after velocity, spin or radius change.
void reclassify(Ball& ball) { ball.state.motion = classify(ball.state, ball.radius); }

}  // namespace

std::optional<Assignment> parseAssignment(std::string_view text)
{
    const std::size_t eq = text.find('=');
    if (eq == std::string_view::npos || eq == 0) return std::nullopt;
    return Assignment{std::string(text.substr(0, eq)), std::string(text.substr(eq + 1))};
}

std::optional<double> parseNumber(std::string_view text)
{
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    if (text.empty() || text.front() == '+') return std::nullopt;
    double x = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(x)) return std::nullopt;
    return x;
}

std::variant<Parameter, OverrideError> Parameter::resolve(const Setup& setup, std::string_view key)
{
    for (const KeyInfo& k : kKeys) {
        if (key != k.name) continue;
        if (isShotField(k.field) && !setup.shot)
            return unknownKey(key, "the setup has no shot to override");
        if (isGameField(k.field) && k.field != Field::GameRules && !setup.game)
            return unknownKey(key, "the setup has no game; set game.rules first");
        return Parameter(std::string(key), k.field, -1);
    }
    // A cushion model's own parameter, from the registry: a key of the setup's current model only, as
    // in the file (a model's key with another model is refused there as a typo would be).
    if (key.substr(0, kCushionPrefix.size()) == kCushionPrefix) {
        const auto [owner, parameter] = findModelParameter(key.substr(kCushionPrefix.size()));
        if (parameter) {
            const CushionModelEntry& current = cushionModel(setup.physics.ballCushionModel);
            if (owner != &current)
                return unknownKey(key, "a parameter of the " + std::string(owner->name) + " model, and the setup's model is " +
                                           std::string(current.name) + "; set physics.ball_cushion.model=" +
                                           std::string(owner->name) + " first");
            Parameter p(std::string(key), Field::CushionModelParameter, -1);
            p.member_ = parameter->field;
            return p;
        }
    }
    constexpr std::string_view ballsPrefix = "balls.";
    if (key.substr(0, ballsPrefix.size()) == ballsPrefix) {
        const std::string_view rest = key.substr(ballsPrefix.size());
        const std::size_t dot = rest.rfind('.');
        if (dot == std::string_view::npos || dot == 0)
            return unknownKey(key, "expected balls.<id>.x|y|vx|vy|wx|wy|wz|radius|mass");
        const std::string_view id = rest.substr(0, dot), name = rest.substr(dot + 1);
        int index = -1;
        for (std::size_t i = 0; i < setup.balls.size(); ++i)
            if (setup.balls[i].id == id) index = static_cast<int>(i);
        if (index < 0) {
            std::vector<std::string> ids;
            for (const Ball& b : setup.balls) ids.push_back(quoted(b.id));
            return unknownKey(key, "there is no ball " + quoted(id) +
                                       (ids.empty() ? std::string("; the setup has no balls") : "; the balls are " + joined(ids, ", ")));
        }
        for (const KeyInfo& k : kBallKeys)
            if (name == k.name) return Parameter(std::string(key), k.field, index);
        return unknownKey(key, "a ball has x, y, vx, vy, wx, wy, wz, radius and mass");
    }
    return unknownKey(key, validKeys(setup));
}

Parameter::Type Parameter::type() const
{
    return field_ == Field::CushionModelParameter ? Type::Number : infoOf(field_).type;
}

double Parameter::number(const Setup& s) const
{
    const Ball* ball = ball_ >= 0 ? &s.balls[static_cast<std::size_t>(ball_)] : nullptr;
    switch (field_) {
    case Field::ShotSpeed: return s.shot->speed;
    case Field::ShotHeading: return s.shot->headingDeg;
    case Field::ShotElevation: return s.shot->elevationDeg;
    case Field::ShotSide: return s.shot->side;
    case Field::ShotHeight: return s.shot->height;
    case Field::ShotCueMass: return s.shot->cueMass;
    case Field::ShotEndMass: return s.shot->endMass;
    case Field::Gravity: return s.physics.gravity;
    case Field::MuSlide: return s.physics.muSlide;
    case Field::MuRoll: return s.physics.muRoll;
    case Field::MuSpin: return s.physics.muSpin;
    case Field::BallBallRestitution: return s.physics.ballBallRestitution;
    case Field::BallBallFriction: return s.physics.ballBallFriction;
    case Field::BallCushionRestitution: return s.physics.cushionRestitution;
    case Field::BallCushionFriction: return s.physics.cushionFriction;
    case Field::CushionModelParameter: return s.physics.*member_;
    case Field::TableLength: return s.table.length.value_or(makeTable(s.table.kind).length);
    case Field::TableWidth: return s.table.width.value_or(makeTable(s.table.kind).width);
    case Field::TableCushionHeight: return s.table.cushionHeight.value_or(makeTable(s.table.kind).cushionHeight);
    case Field::BallX: return ball->state.position.x();
    case Field::BallY: return ball->state.position.y();
    case Field::BallVx: return ball->state.velocity.x();
    case Field::BallVy: return ball->state.velocity.y();
    case Field::BallWx: return ball->state.spin.x();
    case Field::BallWy: return ball->state.spin.y();
    case Field::BallWz: return ball->state.spin.z();
    case Field::BallRadius: return ball->radius;
    case Field::BallMass: return ball->mass;
    case Field::MaxTime: return s.simulation.maxTime;
    case Field::FrameDt: return s.simulation.frameDt;
    default: return 0.0;
    }
}

std::string Parameter::text(const Setup& s) const
{
    switch (field_) {
    case Field::ShotBall: return s.shot->ball;
    case Field::Name: return s.name;
    case Field::Notes: return s.notes;
    case Field::BallBallModel: return std::string(toString(s.physics.ballBallModel));
    case Field::BallCushionModel: return std::string(toString(s.physics.ballCushionModel));
    case Field::TableKind: return std::string(toString(s.table.kind));
    case Field::TablePockets: return s.table.pockets ? "true" : "false";
    case Field::GameRules: return s.game ? std::string(toString(s.game->rules)) : "none";
    case Field::GameGroup: return std::string(toString(s.game->group.value_or(PoolGroup::Open)));
    case Field::GameOn: return std::string(toString(s.game->on.value_or(SnookerOn::Red)));
    case Field::GameNominated: return s.game->nominated;
    case Field::GameBreak: return s.game->breakShot ? "true" : "false";
    case Field::BallBallFriction:
        if (s.physics.ballBallFrictionKind == BallBallFriction::Alciatore) return "alciatore";
        return numberText(number(s));
    default: return numberText(number(s));
    }
}

void Parameter::setNumber(Setup& s, double x) const
{
    Ball* ball = ball_ >= 0 ? &s.balls[static_cast<std::size_t>(ball_)] : nullptr;
    switch (field_) {
    case Field::ShotSpeed: s.shot->speed = x; break;
    case Field::ShotHeading: s.shot->headingDeg = x; break;
    case Field::ShotElevation: s.shot->elevationDeg = x; break;
    case Field::ShotSide: s.shot->side = x; break;
    case Field::ShotHeight: s.shot->height = x; break;
    case Field::ShotCueMass: s.shot->cueMass = x; break;
    case Field::ShotEndMass: s.shot->endMass = x; break;
    case Field::Gravity: s.physics.gravity = x; break;
    case Field::MuSlide: s.physics.muSlide = x; break;
    case Field::MuRoll: s.physics.muRoll = x; break;
    case Field::MuSpin: s.physics.muSpin = x; break;
    case Field::BallBallRestitution: s.physics.ballBallRestitution = x; break;
    case Field::BallBallFriction:
        s.physics.ballBallFrictionKind = BallBallFriction::Fixed;
        s.physics.ballBallFriction = x;
        break;
    case Field::BallCushionRestitution: s.physics.cushionRestitution = x; break;
    case Field::BallCushionFriction: s.physics.cushionFriction = x; break;
    case Field::CushionModelParameter: s.physics.*member_ = x; break;
    case Field::TableLength: s.table.length = x; break;
    case Field::TableWidth: s.table.width = x; break;
    case Field::TableCushionHeight: s.table.cushionHeight = x; break;
    case Field::BallX: ball->state.position.x() = x; break;
    case Field::BallY: ball->state.position.y() = x; break;
    case Field::BallVx: ball->state.velocity.x() = x; reclassify(*ball); break;
    case Field::BallVy: ball->state.velocity.y() = x; reclassify(*ball); break;
    case Field::BallWx: ball->state.spin.x() = x; reclassify(*ball); break;
    case Field::BallWy: ball->state.spin.y() = x; reclassify(*ball); break;
    case Field::BallWz: ball->state.spin.z() = x; reclassify(*ball); break;
    case Field::BallRadius: ball->radius = x; reclassify(*ball); break;
    case Field::BallMass: ball->mass = x; break;
    case Field::MaxTime: s.simulation.maxTime = x; break;
    case Field::FrameDt: s.simulation.frameDt = x; break;
    default: break;
    }
}

std::optional<OverrideError> Parameter::setText(Setup& s, std::string_view value) const
{
    switch (field_) {
    case Field::ShotBall: {
        for (const Ball& b : s.balls)
            if (b.id == value) {
                s.shot->ball = std::string(value);
                return std::nullopt;
            }
        return badValue(key_, value, "the id of a ball");
    }
    case Field::BallBallModel:
        if (value == "frictionless") s.physics.ballBallModel = BallBallModel::Frictionless;
        else if (value == "frictional") s.physics.ballBallModel = BallBallModel::Frictional;
        else return badValue(key_, value, "frictionless or frictional");
        return std::nullopt;
    case Field::BallCushionModel:
        // Every registered model (CushionModels.cpp), by its name in files.
        if (const CushionModelEntry* model = findCushionModel(value)) s.physics.ballCushionModel = model->model;
        else return badValue(key_, value, cushionModelNames());
        return std::nullopt;
    case Field::Name: s.name = std::string(value); return std::nullopt;
    case Field::Notes: s.notes = std::string(value); return std::nullopt;
    case Field::TableKind: {
        TableKind kind{};
        if (!parseTableKind(value, kind))
            return badValue(key_, value, tableKindNames());
        // Balls that followed the old kind's default follow the new one (see Override.h).
        const Table before = makeTable(s.table.kind), after = makeTable(kind);
        for (Ball& b : s.balls) {
            if (b.radius == before.ballRadius) b.radius = after.ballRadius;
            if (b.mass == before.ballMass) b.mass = after.ballMass;
            reclassify(b);
        }
        s.table.kind = kind;
        return std::nullopt;
    }
    case Field::GameRules: {
        if (value == "none") {
            s.game.reset();
            return std::nullopt;
        }
        cuelab::GameRules rules{};
        if (!parseGameRules(value, rules)) return badValue(key_, value, gameRulesNames() + " (or none)");
        // Keys of the old rules that the new ones do not have go (a group is 8-ball's, ...).
        GameSpec game = s.game.value_or(GameSpec{});
        game.rules = rules;
        if (rules != cuelab::GameRules::EightBall) game.group.reset();
        if (rules != cuelab::GameRules::Snooker) game.on.reset();
        if (rules == cuelab::GameRules::Snooker || rules == cuelab::GameRules::ThreeCushion) game.breakShot = false;
        s.game = game;
        return std::nullopt;
    }
    case Field::GameGroup: {
        PoolGroup group{};
        if (!parsePoolGroup(value, group)) return badValue(key_, value, poolGroupNames());
        s.game->group = group;
        return std::nullopt;
    }
    case Field::GameOn: {
        SnookerOn on{};
        if (!parseSnookerOn(value, on)) return badValue(key_, value, snookerOnNames());
        s.game->on = on;
        return std::nullopt;
    }
    case Field::GameNominated: s.game->nominated = std::string(value); return std::nullopt;
    case Field::GameBreak:
        if (value == "true") s.game->breakShot = true;
        else if (value == "false") s.game->breakShot = false;
        else return badValue(key_, value, "true or false");
        return std::nullopt;
    case Field::TablePockets:
        if (value == "true") s.table.pockets = true;
        else if (value == "false") s.table.pockets = false;
        else return badValue(key_, value, "true or false");
        return std::nullopt;
    case Field::BallBallFriction:
        if (value == "alciatore") {
            s.physics.ballBallFrictionKind = BallBallFriction::Alciatore;
            return std::nullopt;
        }
        if (const auto x = parseNumber(value)) {
            setNumber(s, *x);
            return std::nullopt;
        }
        return badValue(key_, value, "a number or \"alciatore\"");
    default:
        if (const auto x = parseNumber(value)) {
            setNumber(s, *x);
            return std::nullopt;
        }
        return badValue(key_, value, "a finite number");
    }
}

std::optional<OverrideError> applyOverride(Setup& setup, std::string_view key, std::string_view value)
{
    auto resolved = Parameter::resolve(setup, key);
    if (auto* error = std::get_if<OverrideError>(&resolved)) return *error;
    return std::get<Parameter>(resolved).setText(setup, value);
}

std::vector<std::string> overridableKeys(const Setup& setup, bool numbersOnly)
{
    std::vector<std::string> keys;
    for (const KeyInfo& k : kKeys) {
        if (numbersOnly && k.type != Type::Number) continue;
        if (isShotField(k.field) && !setup.shot) continue;
        if (isGameField(k.field) && !setup.game) continue;
        keys.emplace_back(k.name);
        // The current cushion model's own parameters, from the registry, after its common ones.
        if (k.field == Field::BallCushionFriction)
            for (const CushionModelParameter& q : cushionModel(setup.physics.ballCushionModel).parameters)
                keys.push_back(std::string(kCushionPrefix) + std::string(q.key));
    }
    for (const Ball& b : setup.balls)
        for (const KeyInfo& k : kBallKeys) keys.push_back("balls." + b.id + "." + k.name);
    return keys;
}

}  // namespace cuelab::analysis
