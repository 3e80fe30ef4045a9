#pragma once
// The cue strike: an instantaneous point impact of the cue tip on the ball (Dr. Dave Alciatore,
// technical proof A-30, and its general form for an elevated cue as used by Leckie & Greenspan).

#include "Ball.h"
#include "CueStrike.h"
#include "Types.h"

namespace cuelab {

struct CueImpactResult {
    BallState after;                   // sliding (or rolling, for b = 2R/5 on a level cue)
    Vec3 impulse = Vec3::Zero();       // N s, on the ball, table frame (its z part is discarded)
    Vec2 contactPoint = Vec2::Zero();  // m, the tip contact projected on the cloth plane
    Vec2 heading = Vec2::Zero();       // unit horizontal direction of the cue
};

// The ball's state just after the strike. The tip offsets (strike.side, strike.height, fractions of
// R) locate the contact point Q = a s + b z - c d relative to the centre, with d the horizontal
// heading, s = d x z the player's right, z up, and c = sqrt(R^2 - a^2 - b^2): a is measured
// sideways and b vertically, whatever the elevation theta. The cue drives along
// e = cos(theta) d - sin(theta) z. Treating the tip as a free body of mass M hitting elastically
// the impulse along e is
//     F = 2 M V0 / (1 + M/m + M |Q x e|^2 / I),   |Q x e|^2 = a^2 + b^2 cos^2 + c^2 sin^2 - 2 b c sin cos,
// the ball gets v = F/m e (its vertical part discarded on the cloth) and w = Q x (F e) / I.
// For theta = 0 this is PHYSICS.md's v = 2 V0 / (1 + m/M + 5 (a^2 + b^2) / (2 R^2)) and
// w = (5 v / (2 R^2)) (a z + b (z x d)). Offsets beyond the ball's silhouette are clamped to it.
CueImpactResult resolveCueStrike(const BallState& before, double radius, double mass, const CueStrike& strike);

}  // namespace cuelab
