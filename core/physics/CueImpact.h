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
    double squirt = 0.0;               // rad, the ball's direction minus the cue's (counter-clockwise +)
};

// Squirt (Alciatore, technical proof A-31): a cue tip of end mass me striking a ball of mass m at the
// side offset a (a fraction of R, + = right) sends the ball off the cue line, away from the side of
// the english, by
//     alpha = atan( (5/2) a sqrt(1 - a^2) / (1 + m/me + (5/2)(1 - a^2)) ).
// Returns alpha in radians, positive for right english (the ball then leaves to the left of the cue
// line, i.e. its heading turns counter-clockwise seen from above). 0 when me <= 0 (no squirt).
double squirtAngle(double side, double ballMass, double endMass);

// The intermediate numbers of resolveCueStrike, for core/explain (filled only when asked for).
struct CueImpactTrace {
    double a = 0.0, b = 0.0;      // m, side and height offsets of the tip (after clamping)
    bool clamped = false;         // the offsets lay beyond the silhouette and were scaled onto it
    double c = 0.0;               // m, sqrt(R^2 - a^2 - b^2), depth of the contact behind the centre
    double phi = 0.0, theta = 0.0;  // rad, heading and elevation
    Vec3 heading = Vec3::Zero();  // d
    Vec3 right = Vec3::Zero();    // s = d x z
    Vec3 axis = Vec3::Zero();     // e = cos(theta) d - sin(theta) z
    Vec3 contact = Vec3::Zero();  // Q = a s + b z - c d, relative to the centre
    double inertia = 0.0;         // kg m^2, 2/5 m R^2
    double lever2 = 0.0;          // m^2, |Q x e|^2
    double impulse = 0.0;         // N s, F
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
// With strike.endMass > 0 the ball's horizontal velocity is then turned by squirtAngle (speed and
// spin stay those of A-30, as in pooltool: A-31 gives the direction only); with endMass = 0 the result
// is bit for bit the one without squirt. The trace holds the A-30 numbers, before the squirt turn.
CueImpactResult resolveCueStrike(const BallState& before, double radius, double mass, const CueStrike& strike,
                                 CueImpactTrace* trace = nullptr);

}  // namespace cuelab
