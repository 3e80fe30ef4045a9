#pragma once
// The elevated strike keeps its vertical part (CONTRACT.md, "Airborne balls"; PHYSICS.md, "Jump
// shot"). The cue at elevation theta drives along e = cos(theta) d - sin(theta) z with the impulse F of
// Alciatore's TP A-30 (CueImpact.h); the ball gets the velocity F e / m, whose vertical part
// -F sin(theta) / m points into the cloth. The cloth answers at once, as a bounce (resolve/
// TableModel.h, the registry's model): the ball leaves with e_table F sin(theta) / m upwards and the
// bounce's friction on its slip. With e_table > 0 every elevated strike leaves the cloth; a steep,
// firm one jumps. A level strike (theta = 0) is exactly CueImpact's, on the cloth.
//
// The strike and the bounce are taken one after the other (the contract's `ball-table` event at t = 0
// follows the cue strike), as pooltool does: the cloth's reaction during the tip's contact is not
// coupled into A-30's impulse.

#include "CueImpact.h"
#include "CueStrike.h"
#include "Flight.h"
#include "Parameters.h"
#include "resolve/TableModel.h"

namespace cuelab {

struct ElevatedStrikeResult {
    CueImpactResult cue;         // A-30, as resolveCueStrike gives it (cue.impulse keeps its z part)
    double vzIntoCloth = 0.0;    // m/s, F e_z / m: the vertical velocity the cue gives (<= 0)
    bool bounced = false;        // the ball was driven into the cloth (vzIntoCloth < 0)
    TableImpactResult bounce;    // the cloth's answer at t = 0 (when bounced)
    AirState after;              // the state leaving t = 0 (airborne when bounced and e_table > 0)
};

ElevatedStrikeResult resolveElevatedStrike(const BallState& before, double radius, double mass, const CueStrike& strike,
                                           const PhysicsParams& p);

}  // namespace cuelab
