#pragma once
// Times of impact (PHYSICS.md, "Event detection"). Every function takes the balls' paths expressed
// from a common time origin s = 0 ("now") and a horizon H (s) up to which those paths are valid,
// and returns the first s in [0, H] at which the contact begins, or kNever.
//
// A contact begins where the gap function crosses zero downwards (the bodies approach). A pair that
// is already touching (gap within kContactTolerance) begins a contact at s = 0 if it approaches
// now; a touching pair that separates is not in contact again until its gap function comes back down
// through zero, so a collision is never found twice at the same instant unless the bodies approach
// again.

#include "Motion.h"
#include "Table.h"

namespace cuelab {

// m: bodies closer than this (or overlapping by rounding) count as touching.
inline constexpr double kContactTolerance = 1e-10;

// Two balls: |d(s)|^2 = (Ra + Rb)^2 with d = pb - pa quadratic in s gives a quartic.
double ballBallTime(const Path& a, double ra, const Path& b, double rb, double horizon);

// A ball and a straight cushion nose: (p(s) - seg.a) . N = R, a quadratic, and the foot of the
// perpendicular must lie on the segment.
double cushionTime(const Path& p, double radius, const CushionSegment& seg, double horizon);

// A ball and a jaw tip: |p(s) - c| = R + rj, a quartic.
double jawTime(const Path& p, double radius, const JawTip& jaw, double horizon);

// A ball and a pocket: the centre enters the pocket circle, |p(s) - c| = rp, a quartic. A ball
// whose centre is already inside drops at s = 0.
double pocketTime(const Path& p, const Pocket& pocket, double horizon);

}  // namespace cuelab
