#pragma once
// Checks of whole simulation results, one copy for the core suites (through SimulationChecks.h), the
// fuzz targets, the soak (RunChecks.h builds its verdicts from these) and cuelab-bench --check:
// overlaps, balls on the table, momentum, energy, and the continuity of the timelines.
// Standard library and Eigen only, no Qt.

#include "BallContact.h"
#include "Contact.h"
#include "Motion.h"
#include "Simulation.h"

#include <string>
#include <vector>

namespace cuelab::testing {

// A ball of the table's radius and mass at `position`, its motion label classified from the numbers.
Ball ballAt(const Table& table, const std::string& id, const Vec2& position, const Vec2& velocity = Vec2::Zero(),
            const Vec3& spin = Vec3::Zero());

// The deepest overlap (m) of a ball of radius R at p with the straight cushion noses and the jaw
// tips of the table; <= 0 when it touches none. A cushion counts wherever the foot of the
// perpendicular lies on its segment, however far behind its nose the centre is: a ball that has
// tunnelled through a rail is an overlap of more than R, not a ball "in a mouth".
double cushionOverlap(const Table& t, double x, double y, double R);
// The same for a ball that may fly: at its height against the slab of each cushion (3-D).
double cushionOverlap(const Table& t, const BallState& s, double R);

// The largest overlap (m) between two balls or a ball and a cushion nose or jaw in the states s;
// <= 0 when nothing overlaps.
double maxOverlap(const SimulationResult& r, const std::vector<BallState>& s);
inline double maxOverlapAt(const SimulationResult& r, double t) { return maxOverlap(r, r.statesAt(t)); }

// Even-odd point in polygon.
bool insidePolygon(const std::vector<Vec2>& poly, const Vec2& p);

// The mouth of pocket k for a ball of radius R: the region a ball's centre may cross between the
// cloth (centres at least R inside the rail noses) and the pocket circle. Bounded by the two rails'
// last nose points moved R onto the cloth, the rails' ends (the jaws' tangent points), and the two
// facings down to their far ends. Built from the table's own elements: the facings of the pocket
// are the two segments "facing-<pocket>-..." and their jaws' rails end where the facing's jaw is.
std::vector<Vec2> mouthPolygon(const Table& t, const Pocket& k, double R);

// Why the state s of a ball of radius R is not a legal place, or "" when it is. Legal is:
//  - pocketed: in the pocket's drop path, which the simulator reduces to its end: the ball sits at
//    the pocket's centre, still, for good (Simulation.cpp writes that state at the pocket event);
//  - not pocketed: on the cloth, its centre at least R - 1e-9 m inside the rail noses (the
//    rectangle [R, L - R] x [R, W - R]) or crossing a pocket's mouth towards the pocket, in no
//    pocket circle (a centre inside one drops at once), and overlapping no cushion nose or jaw by
//    more than 1e-9 m wherever it is.
std::string placeProblem(const SimulationResult& r, const BallState& s, double R);
inline bool onTable(const SimulationResult& r, const BallState& s, double radius) { return placeProblem(r, s, radius).empty(); }

// The same for ball `index` at time t, which also needs the event that pocketed it: a pocketed
// ball must have dropped into that very pocket at or before t.
std::string placeProblemAt(const SimulationResult& r, int index, double t, const BallState& s);

// Translational plus rotational kinetic energy of all balls (J).
double totalEnergy(const SimulationResult& r, const std::vector<BallState>& s);

bool sameState(const BallState& a, const BallState& b);

// The energy (kinetic, spin included, and m g z in flight) of the balls an event lists, its own
// balls and the held group's other members it changes (Event::group): just before and just after.
struct EventEnergy {
    double before = 0.0;  // J
    double after = 0.0;   // J
};
EventEnergy eventEnergy(const SimulationResult& r, const Event& e);

// Momentum of a ball-ball event: whatever the law (frictionless or frictional, and the hold of a
// push, Contact.h), the impulses between the two balls are equal and opposite, so m1 v1 + m2 v2 in
// the plane is the same before and after. Returns the change (N s); 0 for other events and for a
// grouped event (its after-states include the impulses that re-seat the group's other contacts,
// Contact.h: seatContacts): groupMomentumProblem below checks those by the group's total.
double momentumChange(const SimulationResult& r, const Event& e);

// The balls touching ball `index` at time t, directly or through other touching balls (a gap of at
// most `gap` m between neighbours), `index` included; by index.
std::vector<int> touchingGroup(const SimulationResult& r, const std::vector<BallState>& s, int index, double gap);

// The state of ball `index` just before time t (the limit from the left of its timeline).
BallState stateBefore(const SimulationResult& r, int index, double t);

// m v + (I / R) (w_y, -w_x) (N s): the momentum of a ball less what the cloth's horizontal impulses
// have given it, which they give together with a turn of its horizontal spin (Checks.cpp derives it).
// Impulses through the centre (ball-ball normals, re-seating) change it by their own amount.
Vec2 clothCorrectedMomentum(const BallState& s, double radius, double mass);

// Momentum of the held groups (Contact.h): at every instant with a grouped ball-ball event, the
// group of its balls (the balls touching them, through held gaps of at most kHeldGap) keeps the sum
// of clothCorrectedMomentum from just before to just after the instant (within 1e-12 x n of sum m |v|
// before and after for n balls, plus m kSpeedEpsilon per ball for the snap of a label, + 1e-15 N s):
// re-seating a rolling ball gives the cloth a share (5/7 of the impulse moves the ball), and the
// correction takes it out. Not checked where the group shares its impulses otherwise: a member at
// rest or slower than kRollOffSpeed (the cloth holds it whole, seatContacts) just before or after the
// instant or at any solve within it (a cascade of events at one instant solves the group once per
// event: a segment of the member that begins there, an event's before-state or its law's result), a member touching a
// cushion or jaw, another kind of event of a member at that instant, or the frictional ball-ball
// law (its impulse off the centres turns the spins too). Returns "" or what broke; *worst (if given) receives the
// largest change checked.
std::string groupMomentumProblem(const SimulationResult& r, double* worst = nullptr);

// The state reached from `seg` at time t by its own closed-form motion (through the transitions it
// would make on the way, as stateAt does), without looking at any later segment.
BallState continued(const SimulationResult& r, int index, const MotionSegment& seg, double t);

// Continuity of the timelines, ball by ball: the segment k + 1 begins where segment k's closed-form
// motion has taken the ball by then, in position always and in velocity unless the event that began
// it legitimately changes the velocity (a collision or the cue strike involving this ball; a pocket
// moves it to the pocket's centre). A segment is begun by an event of this ball at its start time,
// in order, except in a held push (Contact.h), whose group is solved again without an event (at
// another ball's event, or when a frozen direction has turned far enough), or where the timeline is
// only cut at an instant a held group is solved (the same push, label, velocity and spin go on).
// The excuse of a held group is per ball: the ball touches (through gaps of at most kHeldGap) a ball
// of that instant's solve (a ball of a held or grouped event there, or one whose push begins, goes
// on in a new segment or ends there; the ball itself, when its own push does). Its velocity may then
// change by the re-seating of its contacts, at most kHoldSpeed per contact it has there (balls,
// cushions and jaws within kHeldGap). Returns "" or what broke (ball, segment, numbers).
std::string timelineProblem(const SimulationResult& r, double positionTol = 1e-9, double velocityTol = 1e-9);

}  // namespace cuelab::testing
