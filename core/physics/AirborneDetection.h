#pragma once
// Times of impact with flying balls (PHYSICS.md, "Airborne balls, jumps and massé"). The conventions
// are Detection.h's: paths from a common origin s = 0 ("now"), a horizon H, the first s in [0, H] at
// which a contact begins (the gap crosses zero downwards), or kNever; a touching pair begins a
// contact at s = 0 only if it approaches (kContactTolerance, kRestingSpeed). Roots come from the
// project's solver (Quartic.h, smallestRootInInterval).
//
// Every body is a SpacePath (Flight.h): the centre in space, its height above the cloth included, so
//   a flying ball and a ball on the cloth:  |c_b(s) - c_a(s)|^2 - (Ra + Rb)^2, the height of the flying
//       one quadratic in s: a quartic, as on the cloth;
//   two flying balls: the same gravity cancels in c_b - c_a, which is linear in s: a quadratic (the
//       quartic's first two coefficients are exactly 0);
//   two balls on the cloth: the centres at heights Ra and Rb, so 3-D contact at Ra + Rb is Detection.h's
//       horizontal touchDistance 2 sqrt(Ra Rb) (BallContact.h).
//
// The cushion (CushionSegment) is a slab: behind its nose line (n = (c - a) . N < 0) up to the
// height h of its nose (Table::cushionHeight). A ball meets
//   its face    (the vertical plane n = 0 below h): n(s) = R while the centre is at or below h, the
//               contact Detection.h's cushionTime finds on the cloth;
//   its nose    (the edge, a line at height h): n^2 + (z_c - h)^2 = R^2 while n >= 0 and z_c >= h, a
//               quartic; the contact normal then points from the edge to the centre, tilted up;
//   or clears it: the centre crosses the nose line (n = 0, going out) with the ball's bottom above the
//               rail top (z_c - R >= h): the ball leaves the table (`ball-off-table`, state `off-table`);
//               so does a ball whose bottom comes down to the rail top (z_c - R = h, descending) with
//               its centre behind the nose line (it came there past the segment's end).
// In each case the foot of the perpendicular must lie on the segment, as on the cloth. Past an end of
// the segment, in front of its nose line, the slab's corner is met: its vertical edge (the horizontal
// distance from the end point is R, the centre at or below h) or its top corner (the distance from
// the end point at height h is R, the centre at or above h), quartics as a ball's. A rail's ends are
// inside its jaws (tangent there), which are met first; a pocket facing's far end, behind the pocket,
// is bare, and a ball flying over the pocket can come to it.

#include "Detection.h"
#include "Flight.h"
#include "Quartic.h"
#include "Table.h"

#include <cstdint>

namespace cuelab {

// |c_b(s) - c_a(s)|^2 - (Ra + Rb)^2 (highest degree first).
Quartic spaceBallBallGap(const SpacePath& a, double ra, const SpacePath& b, double rb);
// The first contact of two balls in space (either may fly).
double spaceBallBallTime(const SpacePath& a, double ra, const SpacePath& b, double rb, double horizon);
// Whether the centres stay at least Ra + Rb - depth apart over [0, horizon] (a finite horizon):
// the deepest the two paths would press into each other, unanswered, is within `depth`.
bool spaceBallBallWithin(const SpacePath& a, double ra, const SpacePath& b, double rb, double depth, double horizon);

enum class CushionContactKind : std::uint8_t {
    None,
    Face,      // the ball meets the cushion's face below the nose (as on the cloth)
    Nose,      // the ball meets the nose edge from above it
    OffTable,  // the ball clears the rail: `ball-off-table`
    End,       // the ball meets the front corner of the segment's end (its vertical edge or top corner)
};

struct AirCushionContact {
    double time = kNever;  // s
    CushionContactKind kind = CushionContactKind::None;
    // The contact normal at `time`, unit, from the cushion towards the centre (Face: (N, 0); Nose:
    // tilted; End: from the corner; OffTable: zero).
    Vec3 normal = Vec3::Zero();
};

// n(s)^2 + (z_c(s) - h)^2 - R^2, the nose edge's gap (without its conditions n >= 0, z_c >= h).
Quartic cushionNoseGap(const SpacePath& p, double radius, const CushionSegment& seg, double noseHeight);
// The first of the three contacts above with one cushion segment.
AirCushionContact airCushionContact(const SpacePath& p, double radius, const CushionSegment& seg, double noseHeight,
                                    double horizon);

// A jaw tip is a vertical cylinder of radius rj up to the nose height: a ball meets its side where
// the horizontal distance is R + rj and its centre is at or below h (Detection.h's quartic, with the
// height condition). The jaw's top rim (a torus: degree 8 in s) is not handled: docs/airborne.md.
double airJawSideTime(const SpacePath& p, double radius, const JawTip& jaw, double noseHeight, double horizon);

// The whole jaw tip, a solid cylinder of radius rj from the cloth up to h: its side (above), its flat
// top (the centre at R above it, horizontally within rj of the axis: a quadratic) and its rim, the
// circle of radius rj at height h (the centre at distance R from it while at least rj from the axis
// and at or above h). With rho the horizontal distance from the axis and w = z_c - h,
// (rho - rj)^2 + w^2 = R^2 is 2 rj rho = Q, Q = rho^2 + rj^2 + w^2 - R^2, so Q^2 - 4 rj^2 rho^2 = 0, of
// degree 8 in s (degree 4 in Q); its roots with Q >= 0 are the rim's (the other factor,
// (rho + rj)^2 + w^2 - R^2 = 4 rj rho at a contact, is positive, so the gap falls where it falls).
// Kind Face is the side, Nose the top or the rim; the normal points from the jaw to the centre.
AirCushionContact airJawContact(const SpacePath& p, double radius, const JawTip& jaw, double noseHeight, double horizon);

// A flying ball comes down to the cloth's level (z_c = R, descending) with its centre inside the
// pocket's circle: there is no cloth there, so it drops in (`ball-pocket`) at that time. kNever if it
// lands elsewhere (or not before the horizon). A ball whose centre is over the circle higher up flies
// over the pocket.
double airPocketTime(const SpacePath& p, double radius, const Pocket& pocket, double horizon);
// The interval during which the centre is over the pocket's circle (horizontally), from s >= 0;
// {kNever, kNever} if never before the horizon. For the view and explanations ("flies over").
struct OverPocket {
    double enter = kNever;
    double leave = kNever;
};
OverPocket overPocket(const SpacePath& p, const Pocket& pocket, double horizon);

// The time the centre comes down to the cloth's level, z_c(s) = R descending (the landing of a flight;
// Flight.h's landingTime in the path's terms), or kNever.
double spaceLandingTime(const SpacePath& p, double radius, double horizon);

// The table's outline, as a flying ball leaves it (issue 40): the playing area (the rectangle of the
// rail noses) and, at each pocket, the disc within R of its circle (a centre there is over the pocket
// or its mouth, within reach of dropping in). Over a straight rail the outline is the nose line, where
// a ball clearing the rail leaves the table (above); over a pocket's mouth it is the far side of the
// pocket, so a ball that flies over a pocket leaves the table as its centre passes beyond it, not
// when it comes down metres away.
bool insideOutline(const Table& table, const Vec2& centre, double radius);
// The first s in [0, horizon] at which a flying ball's centre, inside the outline now, leaves it
// (kNever if it does not, or if the centre is outside now, or the path is not a free flight's, whose
// horizontal motion is uniform).
double outlineExitTime(const SpacePath& p, double radius, const Table& table, double horizon);

}  // namespace cuelab
