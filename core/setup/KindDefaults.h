#pragma once
// What a table kind brings with it when a setup leaves it out (CONTRACT.md, Extensions version 3:
// "Table kinds bring their own cloth"). Balls already take their kind's radius and mass (makeTable);
// the physics takes its kind's cloth here. The loader, the editor's Reset Physics and the setup made
// from a recording all ask this one function.
//
// Pool and snooker tables keep PHYSICS.md's defaults (PhysicsParams{}). A carom table gets carom
// cloth: the rolling resistance, sliding and spin friction and the cushion's restitution and friction
// calibrated over 40 recorded three-cushion shots (docs/recordings.md, "Calibration of the cloth and
// the cushions": `cuelab-cli calibrate` with Han 2005 cushions over all 40 shots). Every other value
// is the pool default.

#include "Parameters.h"
#include "Table.h"

namespace cuelab {

PhysicsParams defaultPhysics(TableKind kind);

// The cloth a kind brings: its rolling resistance, sliding and spin friction and the cushion's
// restitution and friction (the values defaultPhysics sets apart from the pool defaults).
// hasKindCloth: `physics` holds exactly `kind`'s cloth. setKindCloth: puts `kind`'s cloth in,
// keeping every other value (the editor's change of table kind, when the cloth was the old kind's).
bool hasKindCloth(const PhysicsParams& physics, TableKind kind);
void setKindCloth(PhysicsParams& physics, TableKind kind);

}  // namespace cuelab
