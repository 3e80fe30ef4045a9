#pragma once
// Sustained contact (PHYSICS.md, "Sustained contact"): pushes, cradles, follow-through into frozen
// balls, a ball driven into a rail by its spin.
//
// Instantaneous impulses cannot represent a push: a ball that keeps accelerating into another gives
// an endless, converging sequence of ever weaker collisions (inelastic collapse). Instead:
//
// 1. The hold rule. When a collision's law would leave two bodies parting slower than kHoldSpeed
//    and the contact forces press them together (solveContacts in ContactForces::Pressed mode says
//    the contact is active: the cloth's friction closes the gap faster than the bodies' curvature
//    |v_t|^2 / D opens it), the micro-bounce is dropped: a normal impulse takes the small separation
//    speed away (that only removes energy, 1/2 m_eff v^2) and the pair is *held*. The chatter this
//    replaces would have ended in the same contact; its amplitude is about v^2 / a, under 0.05 mm at
//    1 cm/s and 2 m/s^2. A pair the forces do not press keeps its law's result exactly (a thin cut).
//    Every impulse of the hold and of a group's re-seating acts on the balls by one rule
//    (contactResponse: a sliding ball takes it all, a rolling one 5/7 and keeps rolling, a ball at
//    rest none), and only a held contact may draw its bodies together: every other one is pushed
//    apart or left alone (seatContacts, a mixed complementarity problem), and released when it parts.
//
// 2. Held motion. While held, a contact carries a normal force N >= 0 through both centres (no
//    torque). The forces of a group of held contacts solve the linear complementarity problem
//    N >= 0, g >= 0, N g = 0 for the relative normal accelerations g of the contacts (solveContacts
//    below, an active-set pivoting method, deterministic). Each ball then moves in closed form with
//    the constant acceleration of Motion.h's pushed motion: a sliding ball a = N/m - mu_s g e, a
//    rolling one a = 5/7 N/m - mu_r g d (static friction keeps it rolling: its effective mass is
//    7/5 m), a ball at rest starts rolling when the push beats its rolling resistance and stays put
//    (as a wall) otherwise. The forces are constant until a ball's state ends (a slip or a roll ends:
//    then the group is solved again) or any event touches the group.
//
// What is exact and what is not: when the contact normals, slips and velocities all lie along one
// line (a head-on push, Newton's cradle, a line of frozen balls, a ball pressed straight into a
// rail) the friction directions never turn and the motion is the exact closed form, with the pair's
// distance constant to rounding. Off that line the slip directions and the normal turn during the
// push and there is no closed form: the simulator freezes each friction direction and each normal
// over a segment and ends the segment before any of them turns by more than kMaxTurn (solving
// again there). The frozen normal force does no work (the relative normal velocity stays zero) and
// the frozen friction only dissipates (each slip keeps a positive component along its frozen
// direction), so the energy still never rises, and the held pair's distance only grows (by the
// square of the tangential displacement), so it never overlaps; a pair that drifts apart is simply
// released and meets again by ordinary detection. Never adding energy is exact in both cases.

#include "Ball.h"
#include "Parameters.h"
#include "Types.h"

#include <cstdint>
#include <vector>

namespace cuelab {

// m/s: a collision whose law leaves a pressed pair parting slower than this holds the pair instead.
inline constexpr double kHoldSpeed = 0.01;

// rad: the largest turn of a frozen friction direction or contact normal within one held segment.
inline constexpr double kMaxTurn = 1e-2;

// m: the widest gap a held contact may open before it counts as parted (the frozen normal of a push
// off the line of centres opens it slowly), and the most one segment may add to it.
inline constexpr double kHeldGap = 1e-7;
inline constexpr double kSegmentGap = 1e-9;

// m/s^2: a held contact whose bodies part with a relative normal acceleration below this (rounding,
// or two balls rolling side by side at one speed) stays held with no force.
inline constexpr double kRestingAcceleration = 1e-9;

// m/s: the most a frozen rolling direction may cost a held segment in velocity (the rolling
// resistance mu_r g acting along a direction off the true one by the turn): a slow rolling ball pushed
// sideways turns fast, and kMaxTurn alone would cut its turn into ever shorter segments.
inline constexpr double kTurnSpeedError = 1e-7;

// m/s: a pushed rolling ball slower than this counts as rolling off from rest (its rolling
// resistance acts against the push, not along a velocity that is rounding). Such a ball would stop
// within 10^-7 s (mu_r g >= 0.1 m/s^2 or so), having moved less than 10^-15 m. At 10^-9 m/s (the value
// until issue 40's third session) two held balls crept at 1.4 nm/s, each pushed by exactly its rolling
// resistance along its velocity, and a ball at rest beside them was met every 0.24 us: a 16-ball break
// took 116 536 events and 132 s (wide-seed12-shot222722); taken as at rest, they stop.
inline constexpr double kRollOffSpeed = 1e-8;

// m: a held ball's slip so small that the cloth would end it within this distance
// (|u|^2 <= 2 * 3.5 mu_s g * this) is rolled out when its contacts are solved (HeldContacts.cpp,
// AirHold.cpp): its direction, and the friction's, would be rounding.
inline constexpr double kSlipRollOutLength = 1e-12;
// A sliding ball whose slip the cloth would end within kSlipRollOutLength: |u|^2 <= 7 mu_s g times it.
bool slipRollsOut(const BallState& s, double radius, const PhysicsParams& p);
// A sliding ball whose slip has as good as ended (Motion.h's slipHasEnded) or rolls out
// (slipRollsOut) rolls out now (Motion.h's rollOut) and is labelled again; true if it did. The air
// hold settles the ball on the cloth with it (AirHold.cpp).
bool rollOutRounding(BallState& s, double radius, const PhysicsParams& p);

// s: the longest held segment (the group is solved again at least this often).
inline constexpr double kMaxHeldSegment = 0.25;

// The cost of a held group is bounded by design (issue 40; docs/sustained-contact.md, "Issue 40"): a
// group solved again without an event more than kQuietSolves times in a row (a quiet stretch, since
// the last event of any of its balls) no longer lets its accuracy limits (how far a frozen slip or
// roll direction turns, how far a held pair's frozen normal turns or its distance grows) cut a segment
// shorter than 1/kQuietSolves of the stretch so far. Its segments then grow geometrically, so a
// stretch of length T whose first segment lasted s0 costs at most about kQuietSolves (1 + ln(T / s0))
// solves, and memory (segments) stays within that many per event. The limits that keep a held
// contact from overlapping or leaving its body (the curvature allowance, a foot leaving its cushion,
// a jaw's arc, a flying ball's height) are never relaxed, nor a ball's own transition (its slip or
// roll along the frozen direction ends), so energy still never rises and nothing overlaps.
inline constexpr int kQuietSolves = 32;

enum class ContactBody : std::uint8_t { Ball, Cushion, Jaw };

struct ComplementarityTrace;  // ContactTrace.h: the numbers of a solve, for the explanation

// A contact of ball `a` with another ball, a straight cushion or a jaw tip (indices into the
// simulator's lists).
struct HeldContact {
    int a = -1;
    ContactBody body = ContactBody::Ball;
    int other = -1;
    double since = 0.0;  // s, when it began to be held (the simulator's bookkeeping; not compared)
    // Held without the curvature allowance (its forces keep the frozen normal's distance): its
    // tangential motion slows too fast for the allowance (the simulator's bookkeeping; not compared).
    bool flat = false;
    // Its last solve's answer (1 pressed, 0 not, -1 none): where the next solve of its group begins
    // its pivoting (solveContacts' `warm`; the simulator's bookkeeping, not compared).
    signed char pressed = -1;
    bool operator==(const HeldContact& o) const { return a == o.a && body == o.body && other == o.other; }
};

// One ball of a group as the solver sees it: its state (with the motion label the simulator keeps)
// and its constants.
struct ContactBall {
    BallState state;
    double radius = 0.0;  // m
    double mass = 0.0;    // kg
};

// A contact for the solver: balls by their place in the group's list; `b` < 0 for a fixed body.
// A link of two balls on the cloth lies in the plane. A link with a flying ball (state.motion
// Airborne: a ball pressed from above on a ball of the group, issue 23) has a tilted normal: `normal`
// is then its horizontal part and `nz` its vertical part, (normal, nz) unit. The flying ball answers
// a force in all three directions (1/m, and gravity is its free acceleration); a ball on the cloth
// answers only its horizontal part (the cloth takes the vertical one).
struct ContactLink {
    int a = -1;
    int b = -1;
    Vec2 normal = Vec2::Zero();  // unit, from a towards the other body (its horizontal part: above)
    double nz = 0.0;             // the normal's vertical part, up (0 for a link in the plane)
    // m/s^2: |v_t|^2 / D, the relative tangential speed squared over the distance between the centre of
    // a and the other body's centre (or, for a straight cushion, 0). Two bodies that slide past each
    // other at the distance D part with this normal acceleration even with no force between them: the
    // term of |d|'' that Detection.cpp's resting-contact test has, so that the solver, the hold and
    // detection answer "pressed?" alike.
    double curvature = 0.0;
};

// How a ball's centre answers an impulse or force F through it (Contact.h's one rule, for the hold of
// a collision, the re-seating of a group and the forces alike): its velocity changes by c F / m with
//   c = 1    sliding (the cloth's kinetic friction does not react to it at once),
//   c = 5/7  rolling (static friction keeps it rolling: its spin follows, the cloth takes 2/7),
//   c = 0    at rest, spinning in place or rolling off from rest slower than kRollOffSpeed (the cloth
//            holds it against what a contact can do at once;
//            the force solver lets such a ball roll off when the push beats its rolling resistance).
double contactResponse(const BallState& s);

// Applies a horizontal impulse J (N s) through the centre of a ball by that rule: v += c J / m, and a
// rolling ball's horizontal spin follows its velocity (it keeps rolling). A ball at rest is unchanged.
void applyContactImpulse(BallState& s, double radius, double mass, const Vec2& J);

struct ContactSolution {
    std::vector<double> force;       // N, per link (>= 0)
    std::vector<char> active;        // per link: held (carries the constraint g = 0)
    std::vector<double> accel;       // m/s^2, per link: the relative normal acceleration g (>= 0)
    std::vector<Vec2> push;          // m/s^2, per ball: its net contact force over its mass
    std::vector<double> pushZ;       // m/s^2, per ball: its vertical part (a flying ball's; else 0)
    std::vector<MotionState> label;  // per ball: the motion label of its pushed segment
    // false when the pivoting ran out of steps: then the forces are the projected Gauss-Seidel
    // iteration's (non-negative, complementary to rounding only approximately), never dropped.
    bool converged = true;
};

// Which relative normal acceleration the forces are solved for.
//   Pressed: the true one, n.(a_b - a_a) + curvature: does the group press this contact now? (the
//            one test of "pressed", shared with detection's resting contact);
//   Held:    the forces of a held segment, whose normals are frozen over it: with kHeldCurvatureShare
//            of the curvature, so that the pair's distance grows by (1 - share) curvature s^2 / 2 over
//            a segment, far above the third-order error of the frozen normal (the segment turns the
//            normal by at most about 2e-4 rad, turnLimit): a held pair never overlaps, and what its
//            frozen normal leaves of relative normal speed, (1 - share) curvature s, is small for the
//            re-seating to take away.
inline constexpr double kHeldCurvatureShare = 0.9;
enum class ContactForces : std::uint8_t { Pressed, Held };

// The forces of a group of touching bodies whose relative normal velocities are zero.
// `maxPivots` bounds the active-set pivoting (< 0: the default, 8 per link + 16); tests pass 0 to
// reach the Gauss-Seidel fallback. `warm` (per link: 1 pressed, 0 not, -1 unknown) is where the
// pivoting begins, a previous solve of the same contacts; the answer is the problem's either way
// (the pivoting ends only at a complementary solution), only found in fewer steps.
ContactSolution solveContacts(const std::vector<ContactBall>& balls, const std::vector<ContactLink>& links,
                              const PhysicsParams& p, ContactForces mode = ContactForces::Held,
                              int maxPivots = -1, const std::vector<signed char>* warm = nullptr,
                              ComplementarityTrace* trace = nullptr);

// Re-seating: normal impulses at the links, applied together by contactResponse's rule, so that
//   - a held link (held[k] != 0: its forces press it, or it is a collision's hold) ends with no
//     relative normal velocity, vn' = 0: it may draw its bodies together, by at most its vn
//     (<= kHoldSpeed), the micro-bounce the pressing force would end anyway;
//   - any other link is compressive only: P >= 0, vn' >= 0, P vn' = 0 (a pair that parts keeps
//     parting, and is released by the caller);
// a mixed linear complementarity problem on the impulses. vn: m/s per link, > 0 parting.
struct Seating {
    std::vector<double> impulse;  // N s per link, > 0 pushing apart, < 0 drawing together
    std::vector<double> after;    // m/s per link, the relative normal velocity after
    bool converged = true;
};
Seating seatContacts(std::vector<ContactBall>& balls, const std::vector<ContactLink>& links,
                     const std::vector<double>& vn, const std::vector<char>& held,
                     ComplementarityTrace* trace = nullptr);

}  // namespace cuelab
