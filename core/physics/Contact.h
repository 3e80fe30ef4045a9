#pragma once
// Sustained contact (PHYSICS.md, "Sustained contact"): pushes, cradles, follow-through into frozen
// balls, a ball driven into a rail by its spin.
//
// Instantaneous impulses cannot represent a push: a ball that keeps accelerating into another gives
// an endless, converging sequence of ever weaker collisions (inelastic collapse). Instead:
//
// 1. The hold rule. When a collision's law would leave two bodies parting slower than kHoldSpeed
//    while the cloth's friction presses them together (their free accelerations close the gap), the
//    micro-bounce is dropped: a normal impulse takes the small separation speed away (that only
//    removes energy, 1/2 m_eff v^2) and the pair is *held*. The chatter this replaces would have
//    ended in the same contact; its amplitude is about v^2 / a, under 0.05 mm at 1 cm/s and 2 m/s^2.
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

// m/s: a pushed rolling ball slower than this counts as rolling off from rest (its rolling
// resistance acts against the push, not along a velocity that is rounding).
inline constexpr double kRollOffSpeed = 1e-9;

// s: the longest held segment (the group is solved again at least this often).
inline constexpr double kMaxHeldSegment = 0.25;

enum class ContactBody : std::uint8_t { Ball, Cushion, Jaw };

// A contact of ball `a` with another ball, a straight cushion or a jaw tip (indices into the
// simulator's lists).
struct HeldContact {
    int a = -1;
    ContactBody body = ContactBody::Ball;
    int other = -1;
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
struct ContactLink {
    int a = -1;
    int b = -1;
    Vec2 normal = Vec2::Zero();  // unit, from a towards the other body
};

struct ContactSolution {
    std::vector<double> force;       // N, per link (>= 0)
    std::vector<char> active;        // per link: held (carries the constraint g = 0)
    std::vector<double> accel;       // m/s^2, per link: the relative normal acceleration g (>= 0)
    std::vector<Vec2> push;          // m/s^2, per ball: its net contact force over its mass
    std::vector<MotionState> label;  // per ball: the motion label of its pushed segment
    bool converged = true;           // false only if the pivoting ran out of steps (then forces are 0)
};

// The forces of a group of touching bodies whose relative normal velocities are zero.
ContactSolution solveContacts(const std::vector<ContactBall>& balls, const std::vector<ContactLink>& links,
                              const PhysicsParams& p);

// Re-seats held contacts: the normal impulses that bring every link's relative normal velocity
// (vn, m/s, > 0 parting) to zero together, applied to the balls (velocities, and the spins of rolling
// balls, which keep rolling; a ball at rest is held by the cloth and takes no part). Removing relative normal velocity
// never adds energy (it is -1/2 vn.A+ vn). Returns the impulses (N s per link, > 0 pushing apart).
std::vector<double> seatContacts(std::vector<ContactBall>& balls, const std::vector<ContactLink>& links,
                                 const std::vector<double>& vn);

// The acceleration of a ball's centre in its free motion as the solver uses it (m/s^2).
Vec2 freeAcceleration(const BallState& s, double radius, const PhysicsParams& p);

}  // namespace cuelab
