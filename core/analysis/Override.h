#pragma once
// Overriding one value of a setup by its key (CONTRACT.md, Extensions: `--set KEY=VALUE`). The one
// implementation behind `cuelab-cli --set`, the sweep engine's varied parameters and the window's
// Analysis dock.
//
// KEY is a dotted path of the setup file's own names:
//   shot.ball|speed|heading|elevation|side|height|cue_mass|end_mass
//   physics.gravity|mu_slide|mu_roll|mu_spin
//   physics.ball_ball.model|restitution|friction      (friction: a number or "alciatore")
//   physics.ball_cushion.model|restitution|friction   (model: every name of the registry,
//                                                      core/physics/resolve/CushionModels.cpp)
//   physics.ball_cushion.<parameter>                  (the current model's own, from the registry:
//                                                      steps for mathavan2010, omega_ratio for stronge)
//   table.kind|pockets|length|width|cushion_height
//   balls.<id>.x|y|vx|vy|wx|wy|wz|radius|mass         (<id> may itself contain dots)
//   simulation.max_time|frame_dt
//   name|notes                                        (text)
//   game.rules|group|on|nominated|break               (game.rules=none takes the game away; the other
//                                                      game keys need a game; listed only with one)
// so that every key of a setup file can be overridden (CONTRACT.md, Extensions version 2). An unknown
// key's message lists the valid ones; an unknown model lists the registered ones.
//
// Applying an override only checks that the key exists and that the value has the key's type (a
// finite number, true/false, a model or table-kind name, a ball id). Whether the setup is still
// legal (a restitution in [0, 1], a ball on the cloth, ...) is the validator's job afterwards, so
// that an override is refused with exactly the message the loader gives for a file.
//
// table.kind and ball defaults: a setup file may leave a ball's radius and mass out, and they then
// follow the table kind. A Setup in memory holds numbers only, so the rule here is the one the
// writer uses (serializeSetup omits a radius or mass equal to the table's): a ball whose radius
// (mass) equals the old kind's default ball takes the new kind's default; any other value was set
// on purpose and is kept. `table.kind=snooker` on a pool file therefore shrinks the balls as the
// same edit in the file would, while a ball given its own radius keeps it.

#include "Setup.h"

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace cuelab::analysis {

// Why an override could not be applied. Both kinds are usage errors (exit 2 in cuelab-cli).
struct OverrideError {
    enum class Kind { UnknownKey, BadValue };
    Kind kind = Kind::UnknownKey;
    std::string key;      // the KEY as given
    std::string message;  // names the key (and the value): "unknown key \"shot.sped\" (...)"
};

// `KEY=VALUE` split at the first '='; nullopt when there is no '=' or the key is empty.
struct Assignment {
    std::string key;
    std::string value;
};
std::optional<Assignment> parseAssignment(std::string_view text);

// A finite number in the C locale ("3", "-0.5", "1e-3", "+2"); nullopt for anything else.
std::optional<double> parseNumber(std::string_view text);

// A resolved key of a setup: cheap to apply many times (the sweep sets it once per shot).
class Parameter {
public:
    enum class Type { Number, Bool, Text };

    // Resolves `key` against `setup` (a ball key needs the ball, a shot key needs a shot).
    static std::variant<Parameter, OverrideError> resolve(const Setup& setup, std::string_view key);

    const std::string& key() const { return key_; }
    Type type() const;
    bool isNumber() const { return type() == Type::Number; }

    // The current value of a numeric key (for a ball key, of the ball this key resolved to).
    double number(const Setup& setup) const;
    // The current value as text, as --set would take it ("3", "true", "han2005").
    std::string text(const Setup& setup) const;

    // Sets a numeric key. The setup must be the one resolved against (or a copy of it).
    void setNumber(Setup& setup, double value) const;
    // Sets any key from its text; a value of the wrong type is an error naming key and value.
    std::optional<OverrideError> setText(Setup& setup, std::string_view value) const;

    enum class Field : int;  // which value (defined in Override.cpp)

private:
    Parameter(std::string key, Field field, int ball) : key_(std::move(key)), field_(field), ball_(ball) {}
    std::string key_;
    Field field_;
    int ball_ = -1;  // index into Setup::balls for balls.<id>.* keys
    double PhysicsParams::*member_ = nullptr;  // a cushion model's own parameter (its registry entry's field)
};

// Resolves `key` and sets it from text: the whole of `--set KEY=VALUE`.
std::optional<OverrideError> applyOverride(Setup& setup, std::string_view key, std::string_view value);

// Every key of the list above that applies to `setup` (ball keys for each of its balls), in the
// order of the list; for help texts and for the window's parameter choosers.
std::vector<std::string> overridableKeys(const Setup& setup, bool numbersOnly);

}  // namespace cuelab::analysis
