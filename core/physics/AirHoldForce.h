#pragma once
// The contact force of a flying ball held on a ball on the cloth (AirHold.cpp's air hold, issue 23;
// docs/airborne.md, "Held in the air"), in closed form, and the re-seating that begins a hold: the
// simulator's own computation, which the explanation (core/explain) calls with an event's states to
// derive the hold step by step (issue 41), so that the two cannot drift apart.
//
// With n the unit normal from b's centre to a's, n_h its horizontal part, c_b and f_b b's response
// to a push through its centre and its cloth's friction along its frozen direction (Contact.h's
// rule: sliding 1 and -mu_s g e, rolling 5/7 and -mu_r g d; at rest it rolls off along -n_h with
// 5/7 and mu_r g against the push, when 5/7 of the push beats mu_r g, else the cloth holds it:
// c_b = 0), and share |v_t|^2 / d the part of the curvature the force leaves (kHeldCurvatureShare):
//     N (1/m_a + c_b |n_h|^2 / m_b) = g n_z + n_h . f_b - share |v_t|^2 / d.

#include "Ball.h"
#include "Parameters.h"
#include "Types.h"

namespace cuelab {

struct AirHoldForce {
    double force = 0.0;          // N, along the normal (> 0 pressed)
    double gap = 0.0;            // m
    double normalSpeed = 0.0;    // m/s, (v_a - v_b) . n (> 0 parting)
    Vec3 normal = Vec3::Zero();  // n, unit, from b's centre to a's (zero if they coincide)
    Vec3 pushA = Vec3::Zero();   // m/s^2 on a
    Vec2 pushB = Vec2::Zero();   // m/s^2 on b (the cloth takes the vertical part)
    MotionState labelB = MotionState::Stationary;  // b's pushed label (Rolling when it rolls off)
    bool stillB = false;         // b stays at rest: the cloth holds it against the push
    // The terms of N's closed form:
    double curvature = 0.0;        // m/s^2, share |v_t|^2 / d
    double response = 0.0;         // c_b, as it rolls off when it starts from rest
    Vec2 friction = Vec2::Zero();  // m/s^2, f_b
    bool fromRest = false;         // b starts from rest (rolls off, or stillB)
};

// The force of a (radius ra, mass ma, flying) held on b (rb, mb, on the cloth) at their states now;
// force 0 when the centres coincide.
AirHoldForce airHoldForce(const BallState& sa, double ra, double ma, const BallState& sb, double rb, double mb,
                          const PhysicsParams& p);

// The start of a hold from the states at its instant: b's slip of rounding rolled out (Contact.h's
// rollOutRounding), the force solved; a normal speed left by the law or by a frozen normal is taken
// away by an impulse along n (inelastic; b answers by Contact.h's rule), b's slip rolled out again
// and the force solved again from the re-seated states.
struct AirHoldStart {
    bool held = false;       // pressed (N > 0), within kHeldGap and kHoldSpeed
    BallState a, b;          // the states the hold goes on from (labels as they come: the caller's)
    AirHoldForce entering;   // the force from the states it is solved from
    bool reseated = false;   // a normal speed was taken away
    double reseat = 0.0;     // N s, the re-seating impulse along -n on a (+n_h on b's cloth plane)
    double reseatResponse = 0.0;  // c_b of the re-seat (Contact.h's contactResponse of b then)
    AirHoldForce force;      // the hold's force (after the re-seat, when there was one)
};
AirHoldStart startAirHold(BallState sa, double ra, double ma, BallState sb, double rb, double mb, const PhysicsParams& p);

}  // namespace cuelab
