#pragma once
// One event of a simulation, with everything the event list, the inspector and the time-of-impact
// display need: time, kind, agents, and the agents' states just before and just after.

#include "Ball.h"
#include "Types.h"

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace cuelab {

enum class EventKind : std::uint8_t {
    CueStrike,
    BallBall,
    BallCushion,   // a straight cushion segment (rail or facing)
    BallJaw,       // a circular jaw tip; written to files as "ball-cushion" with the jaw's id
    BallPocket,
    SlideToRoll,
    SlideToSpin,
    SlideToStop,
    RollToSpin,
    RollToStop,
    SpinToStop,
    BallTable,     // a ball meets the cloth: a landing, a bounce, or the end of a bounce series
    BallOffTable,  // a ball leaves the table over a cushion (state OffTable)
};

// CONTRACT.md names: "cue-strike", "ball-ball", "ball-cushion" (BallCushion and BallJaw),
// "ball-pocket", "slide-to-roll", ..., "ball-table", "ball-off-table"
// A ball-table event is not a transition (the motion changes by an impulse) nor a collision between
// two bodies (isCollision is false): it has its own kind everywhere.
std::string_view toString(EventKind k);
bool isTransition(EventKind k);
bool isCollision(EventKind k);  // BallBall, BallCushion, BallJaw

struct Event {
    EventKind kind = EventKind::CueStrike;
    double time = 0.0;                 // s
    std::array<int, 2> balls{-1, -1};  // indices into the ball list; balls[1] only for BallBall
    int cushion = -1;                  // index into Table::cushions (BallCushion)
    int jaw = -1;                      // index into Table::jaws (BallJaw)
    int pocket = -1;                   // index into Table::pockets (BallPocket)
    std::array<BallState, 2> before{}; // states of balls[0], balls[1] just before the event
    std::array<BallState, 2> after{};  // and just after

    // Collision details (zero for transitions):
    Vec2 contactPoint = Vec2::Zero();  // m, where the bodies touch (on the cloth plane)
    Vec2 normal = Vec2::Zero();        // unit contact normal, from balls[0] towards the other body
    double approachSpeed = 0.0;        // m/s, normal relative speed just before (> 0 when approaching)
    Vec3 impulse = Vec3::Zero();       // N s, impulse on balls[0] (x, y, z in the table frame)
    // Sustained contact (Contact.h): the law's bodies would part slower than kHoldSpeed while the
    // contact forces press them together, so the collision ends with no normal separation and the
    // pair is held in contact (a push) from here on. `holdImpulse` (N s) is the normal impulse of the
    // re-seating at this contact, signed: > 0 draws the bodies together (it took the law's small
    // separation speed away), < 0 pushes them apart (a held group's other contacts drove them in). It
    // acts on each ball by Contact.h's contactResponse (a rolling ball takes 5/7 of it, the cloth the
    // rest); it is included in `impulse`. A collision that touches a held group but is not pressed
    // (held false, grouped true) may carry one too (< 0 only).
    bool held = false;
    double holdImpulse = 0.0;
    // The event's balls were solved together with other held contacts (a group of three or more
    // bodies): their after-states include the impulses that re-seat those contacts too.
    bool grouped = false;
    // The other balls whose state the event changes (issue 40): the members of the held group solved
    // with it whose velocity, spin or motion label its re-seating or new forces changed, each with its
    // state just before and just after the event's instant. Empty when the event changes its own
    // balls only. With `balls`, an event lists every ball whose state it changes, so that nothing
    // changes silently and the energy of an event can be judged over its own balls.
    struct GroupChange {
        int ball = -1;       // index into the ball list
        BallState before{};  // just before the instant
        BallState after{};   // just after the event
    };
    std::vector<GroupChange> group;
};

}  // namespace cuelab
