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

#include "BallContact.h"
#include "Motion.h"
#include "Quartic.h"
#include "Table.h"

#include <algorithm>

namespace cuelab {

// m: bodies closer than this (or overlapping by rounding) count as touching.
inline constexpr double kContactTolerance = 1e-10;

// m: a ball this far inside a cushion's nose still touches it (a contact now if it approaches or is
// pressed in), so that an overlap a setup may start with (CONTRACT.md's 1e-9 m) or rounding has left
// is held where it is, never deepened. (Two balls touch at any overlap: circleContactTime.)
inline constexpr double kSunkTolerance = 1e-9;

// m/s: a normal speed below this between touching bodies counts as resting contact (neither
// approaching nor parting); the contact begins now if the accelerations press the bodies together.
inline constexpr double kRestingSpeed = 1e-9;

// m/s^2: the part of |d|'' that the motion alone gives two bodies at the relative position d with
// relative velocity v: |v_t|^2 / |d|, v_t the part of v across d (they turn about each other, so
// their distance grows). The one test of "pressed" adds it to the relative normal acceleration
// n.(a_b - a_a): detection's resting contact below, and the held contacts' solver (Contact.h's
// ContactLink::curvature).
inline double separationCurvature(const Vec2& d, const Vec2& v)
{
    const double dist = d.norm();
    const double vn = v.dot(d) / dist;
    return std::max(0.0, v.squaredNorm() - vn * vn) / dist;
}

// The gap functions whose roots are the contacts, as polynomials in s (Quartic order, highest degree
// first). The detection functions below find their roots; core/explain shows them (one code path).
//   two balls:  |pb(s) - pa(s)|^2 - d^2,  d = touchDistance(Ra, Rb) = 2 sqrt(Ra Rb) (Ra + Rb if equal)
//   a cushion:  (p(s) - seg.a) . N - R          (degree 2: the first two coefficients are 0)
//   a jaw:      |p(s) - c|^2 - (R + rj)^2
//   a pocket:   |p(s) - c|^2 - rp^2
Quartic ballBallGap(const Path& a, double ra, const Path& b, double rb);
Quartic cushionGap(const Path& p, double radius, const CushionSegment& seg);
Quartic jawGap(const Path& p, double radius, const JawTip& jaw);
Quartic pocketGap(const Path& p, const Pocket& pocket);

// Whether the foot of the perpendicular from p(s) to the cushion line lies within the segment [a, b].
bool onCushionSegment(const Path& p, const CushionSegment& seg, double s);

// Two balls: |pb(s) - pa(s)|^2 = touchDistance(Ra, Rb)^2, with pb - pa quadratic in s: a quartic.
double ballBallTime(const Path& a, double ra, const Path& b, double rb, double horizon);

// A ball and a straight cushion nose: (p(s) - seg.a) . N = R, a quadratic, and the foot of the
// perpendicular must lie on the segment; or the foot enters the segment through an end (a root of its
// own quadratic) with the ball touching the line and closing in (past a jaw at the junction).
double cushionTime(const Path& p, double radius, const CushionSegment& seg, double horizon);

// A ball and a jaw tip: |p(s) - c| = R + rj, a quartic, the contact on the tip's arc (onJawArc).
double jawTime(const Path& p, double radius, const JawTip& jaw, double horizon);

// A ball and a pocket: the centre enters the pocket circle, |p(s) - c| = rp, a quartic. A ball
// whose centre is already inside drops at s = 0.
double pocketTime(const Path& p, const Pocket& pocket, double horizon);

}  // namespace cuelab
