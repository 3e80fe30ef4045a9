#pragma once
// Ball-cushion collision models: what each one is given, what it returns, and the registry that maps
// a model (BallCushionModel, its file name) to its resolver. Each model lives in its own file in this
// folder (as pooltool keeps one folder per model under physics/resolve/ball_cushion); the registry in
// CushionModels.cpp is the one place that lists them, so a new model is a new file plus one row
// there. The parser, the writer, the Physics panel and the docs read names and parameters from it.

#include "Ball.h"
#include "Parameters.h"
#include "Types.h"

#include <span>
#include <string_view>

namespace cuelab {

struct CushionResult {
    BallState after;              // labelled by classify
    double approachSpeed = 0.0;   // m/s, -(v . N) before; > 0 when approaching
    Vec3 impulse = Vec3::Zero();  // N s, on the ball, table frame
};

// One ball touching a straight cushion nose or a jaw tip. `normal` is the unit normal of the cushion
// at the contact, pointing from the cushion to the ball's centre (a segment's normal; for a jaw tip,
// from the jaw's centre to the ball's). `noseHeight` is the height of the contact line above the
// cloth (m).
struct CushionContact {
    BallState before;
    Vec2 normal = Vec2::Zero();
    double radius = 0.0;      // m
    double mass = 0.0;        // kg
    double noseHeight = 0.0;  // m
};

using CushionResolver = CushionResult (*)(const CushionContact& contact, const PhysicsParams& p);

// A parameter of one model, beyond the restitution and friction every model reads: its key in the
// setup file's "ball_cushion" object, the PhysicsParams member it sets, and its legal range.
struct CushionModelParameter {
    std::string_view key;          // e.g. "steps"
    std::string_view description;  // for people: what it means, its unit and its source
    double PhysicsParams::*field = nullptr;
    double min = 0.0, max = 0.0;   // legal range
    bool minExclusive = false, maxExclusive = false;
    bool integer = false;          // a whole number
    double step = 0.01;            // a sensible increment for a spin box
    int decimals = 3;              // digits a spin box shows
};

struct CushionModelEntry {
    BallCushionModel model;
    std::string_view name;   // in files, on the command line: "mirror", "han2005", ...
    std::string_view title;  // for people: "Han 2005"
    std::string_view summary;  // one sentence for a tooltip
    bool usesFriction = true;  // reads PhysicsParams::cushionFriction
    CushionResolver resolve = nullptr;
    std::span<const CushionModelParameter> parameters;
};

// Every model, in the order the UI lists them.
std::span<const CushionModelEntry> cushionModels();
// The entry of a model (every enumerator has one).
const CushionModelEntry& cushionModel(BallCushionModel model);
// The entry named `name` in files, or nullptr.
const CushionModelEntry* findCushionModel(std::string_view name);

}  // namespace cuelab
