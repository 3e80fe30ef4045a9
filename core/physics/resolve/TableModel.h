#pragma once
// Ball-table impact models: a ball coming down onto the cloth (a landing, a bounce, or the elevated
// cue driving it into the cloth). What each is given, what it returns, and the registry that maps a
// model (BallTableModel, its name in files) to its resolver, as resolve/CushionModel.h does for the
// cushions: each model in its own file in this folder, one row per model in TableModels.cpp.
//
// Every model here is an impulse at the contact point, R below the centre: a normal impulse
// (1 + e) m |vz| that sends the ball up at e |vz|, and a horizontal one that only removes slip. So no
// model adds energy (tst_airborne checks it), and BounceSeries.h can sum their bounces in closed form.

#include "Flight.h"
#include "Parameters.h"
#include "Types.h"

#include <span>
#include <string_view>

namespace cuelab {

struct TableImpactResult {
    AirState after;               // z = 0, vz >= 0; `motion` labelled by classify
    double approachSpeed = 0.0;   // m/s, -vz before (> 0: coming down)
    Vec3 impulse = Vec3::Zero();  // N s, on the ball, table frame (z: the normal impulse)
    bool slipEnded = false;       // the friction was enough to end the slip (the contact point rolls)
};

// One ball meeting the cloth: `before` on the cloth (z = 0, its height is not read) coming down
// (vz < 0; a ball not coming down is returned unchanged).
struct TableContact {
    AirState before;
    double radius = 0.0;  // m
    double mass = 0.0;    // kg
};

using TableResolver = TableImpactResult (*)(const TableContact& contact, const PhysicsParams& p);

struct TableModelEntry {
    BallTableModel model;
    std::string_view name;     // in files (physics.ball_table.model) and on the command line
    std::string_view title;    // for people
    std::string_view summary;  // one sentence for a tooltip
    bool usesFriction = true;  // reads PhysicsParams::tableFriction
    TableResolver resolve = nullptr;
};

// Every model, in the order the UI lists them (the default first).
std::span<const TableModelEntry> tableModels();
// The entry of a model (every enumerator has one).
const TableModelEntry& tableModel(BallTableModel model);
// The entry named `name` in files, or nullptr.
const TableModelEntry* findTableModel(std::string_view name);

// Resolves with the model p.ballTableModel.
TableImpactResult resolveTableImpact(const AirState& before, double radius, double mass, const PhysicsParams& p);

// The friction coefficient the model p.ballTableModel applies (0 for a frictionless model).
double effectiveTableFriction(const PhysicsParams& p);

}  // namespace cuelab
