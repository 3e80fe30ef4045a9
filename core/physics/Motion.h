#pragma once
// Closed-form motion of one ball between events (PHYSICS.md, "Motion between events"): sliding,
// rolling, spinning, stationary and pocketed, and the transitions between those states.
//
// Within one motion state the position is a quadratic polynomial of the elapsed time, the horizontal
// spin is linear (sliding) or follows the velocity (rolling), and |wz| falls linearly to zero in
// every state. A state ends at a transition whose time is known in closed form; evolve() never runs
// past that time (it holds the state reached there), so a caller chains states through transitions.

#include "Ball.h"
#include "Event.h"
#include "Parameters.h"
#include "Types.h"

#include <limits>

namespace cuelab {

inline constexpr double kNever = std::numeric_limits<double>::infinity();

// Moment of inertia of a solid sphere about a diameter, I = 2/5 m R^2 (kg m^2).
inline double ballInertia(double mass, double radius) { return 0.4 * mass * radius * radius; }

// Angular deceleration of the spin about z: alpha = 5 mu_sp g / (2 R) (rad/s^2). PHYSICS.md: the
// torque of the spin friction over I = 2/5 m R^2.
double spinDeceleration(const PhysicsParams& p, double radius);

// Position over the current motion state: r(tau) = c0 + c1 tau + c2 tau^2 for 0 <= tau <= the
// state's duration (the acceleration is constant within a state, so c2 = a / 2).
struct Path {
    Vec2 c0 = Vec2::Zero();  // m
    Vec2 c1 = Vec2::Zero();  // m/s
    Vec2 c2 = Vec2::Zero();  // m/s^2
    Vec2 at(double tau) const { return c0 + tau * (c1 + tau * c2); }
    // The same polynomial expanded about tau0: shifted(tau0).at(s) = at(tau0 + s). The simulator
    // predicts from "now" with it, and core/explain rebuilds the same polynomials with it.
    Path shifted(double tau0) const { return Path{at(tau0), c1 + (2.0 * tau0) * c2, c2}; }
};
Path pathOf(const BallState& s, double radius, const PhysicsParams& p);

// How long the ball stays in its present motion state (kNever for stationary and pocketed balls, or
// a frictionless cloth), and which transition ends it.
struct Transition {
    double after = kNever;                  // s from the state's start
    EventKind kind = EventKind::SpinToStop; // meaningful only when `after` is finite
};
Transition nextTransition(const BallState& s, double radius, const PhysicsParams& p);

// The state `dt` seconds later without leaving the present motion state: dt is clamped to the
// state's duration. The motion label is left as it is.
BallState evolve(const BallState& s, double radius, const PhysicsParams& p, double dt);

// The state just after the transition that ends the present state: evolve() to its end, then make
// the numbers exact (a rolling ball's spin follows its velocity; a ball that stops has v = 0 and
// horizontal w = 0; a stopped spin is 0) and label the result with classify().
BallState applyTransition(const BallState& s, double radius, const PhysicsParams& p);

// Pushed motion (PHYSICS.md, "Sustained contact"; Contact.h): the ball carries, besides the cloth's
// friction, a constant horizontal contact force through its centre, `push` = force / mass (m/s^2).
// Its motion label is taken from s.motion (set by the simulator; a ball pushed from rest is
// labelled Rolling), not from the numbers:
//   Sliding  the cloth's friction keeps the direction e of the slip at the segment's start:
//            a = push - mu_s g e, the spin changes as in a free slide, and the slip
//            u(t) = u0 + (push - 7/2 mu_s g e) t; the state lasts until e.u = 0.
//   Rolling  static friction keeps u = 0 (valid while |push| <= 7/2 mu_s g): a = 5/7 push - mu_r g d,
//            d the direction of the velocity at the segment's start (of push from rest); the state
//            lasts until d.v = 0.
// When push is parallel to e (or d), as in every head-on push and line of balls, that is the exact
// closed form; otherwise e and d turn during the segment and the simulator keeps segments short
// (Contact.h: kMaxTurn). A zero push gives exactly the free functions above.
Path pathOf(const BallState& s, double radius, const PhysicsParams& p, const Vec2& push);
// The duration of the pushed state (kNever if it does not end by itself); `kind` is the free
// transition's kind that its end would be if the state ends at rest or rolling.
Transition nextTransition(const BallState& s, double radius, const PhysicsParams& p, const Vec2& push);
BallState evolve(const BallState& s, double radius, const PhysicsParams& p, double dt, const Vec2& push);
// The state at the end of the pushed state, made exact as applyTransition does when the numbers say
// it ended (slip or velocity zero up to rounding) and labelled with classify().
BallState applyTransition(const BallState& s, double radius, const PhysicsParams& p, const Vec2& push);

// Translational plus rotational kinetic energy (J). A pocketed ball has none.
// A slip no larger than kSlipEnded of the ball's speeds (|v| + R |w_xy|) has as good as ended: its
// direction is rounding, so is the sliding friction it would steer.
inline constexpr double kSlipEnded = 1e-8;
bool slipHasEnded(const BallState& s, double radius);
// Takes the slip off as the cloth does: a friction impulse at the contact point, -2/7 m u on the
// centre, which keeps the angular momentum about that point and never adds energy. The ball rolls.
void rollOut(BallState& s, double radius);

double kineticEnergy(const BallState& s, double radius, double mass);
// Its two parts, 1/2 m |v|^2 and 1/2 I |w|^2 (J); kineticEnergy() is their sum.
double translationalEnergy(const BallState& s, double mass);
double rotationalEnergy(const BallState& s, double radius, double mass);

}  // namespace cuelab
