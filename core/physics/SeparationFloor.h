#pragma once
// The separation floor of Detection.h (kMinSeparationSpeed): after a collision law, an extra normal
// impulse makes the bodies part at least that fast. The simulator applies it after every collision;
// core/explain shows it with the same functions.

#include "BallBallCollision.h"
#include "CushionCollision.h"

namespace cuelab {

// Keeps the separation speed of a ball-ball collision at least kMinSeparationSpeed by an extra
// normal impulse shared as the masses dictate (momentum is kept). Returns the extra impulse (N s,
// along n, on b; 0 when the law already parts them fast enough).
double enforceSeparation(BallBallResult& r, double massA, double massB);

// The same for a ball leaving a cushion or jaw whose normal (towards the ball) is `normal`.
// Returns the extra impulse on the ball (N s, along normal).
double enforceSeparation(CushionResult& r, const Vec2& normal, double mass);

}  // namespace cuelab
