#pragma once
// The aiming geometry of a ball-ball contact, as a player reads it (issue 22, CONTRACT.md version 2:
// `explain` of a ball-ball collision gains `cut_angle` and `ball_fraction`).
//
// At contact the struck ball's centre is the "ghost ball" G, the object ball's centre O lies the
// touch distance D = touchDistance(R_s, R_o) from it (BallContact.h) along the line of centres
// n = (O − G)/D. The cut angle φ is the angle between the struck ball's path d (its velocity just
// before the contact) and n: 0° is a full (straight-on) hit, 30° a half-ball hit, 90° a graze. The
// ball fraction is the share of the object ball the struck ball covers, seen along its path: the
// path passes D sin φ from O, so the overlap is D − D sin φ of the width D, f = 1 − sin φ (1 full,
// 0.5 half ball since sin 30° = ½, 0 a graze). The object ball leaves to the left of the path when n
// lies counter-clockwise of d (d × n > 0): a cut to the left.
//
// Planning a shot inverts this for a straight path from the struck ball's place C: to cut the object
// ball at φ, the path must pass b = D sin φ from O, so the heading is the bearing of O from C turned
// by asin(b / |O − C|), clockwise for a cut to the left (the path passes to the right of O).

#include "Ball.h"
#include "Simulation.h"
#include "Types.h"

#include <optional>

namespace cuelab::aim {

enum class CutSide { Straight, Left, Right };  // where the object ball goes, seen along the path

struct AimGeometry {
    double cutAngleDeg = 0.0;        // degrees, between the path and the line of centres (0..180)
    double ballFraction = 1.0;       // 1 − sin φ, 0 for φ ≥ 90° (no hit along this path)
    CutSide side = CutSide::Straight;
    Vec2 path = Vec2(1.0, 0.0);      // unit direction d of the struck ball at contact
    Vec2 lineOfCentres = Vec2(1.0, 0.0);  // unit n from the struck ball towards the object ball
    Vec2 ghostBall = Vec2::Zero();   // m, the struck ball's centre at contact
    Vec2 objectBall = Vec2::Zero();  // m, the object ball's centre at contact
    Vec2 contactPoint = Vec2::Zero();  // m, on the cloth plane: G + R_s c n (c as in BallContact.h)
    // Where the contact lies on each ball, as a bearing from its centre measured from the struck
    // ball's path (degrees, counter-clockwise +): on the struck ball the signed cut angle, on the
    // object ball that bearing + 180°, wrapped to (−180, 180].
    double contactOnStruckDeg = 0.0;
    double contactOnObjectDeg = 180.0;
    Vec2 aimStart = Vec2::Zero();    // m, where the struck ball set off (the aim line runs from here
                                     // through the ghost ball)
};

// The geometry of a contact with the struck ball at `ghost` moving along `path` (need not be unit;
// zero gives the line of centres as the path, a full hit) and the object ball at `object`. The radii
// give the touch distance and the contact point. `aimStart` is stored as given.
AimGeometry geometryAt(const Vec2& ghost, const Vec2& path, const Vec2& object, double struckRadius,
                       double objectRadius, const Vec2& aimStart);

// A straight path from `from` along the heading (degrees, 0 = +x, counter-clockwise +): the contact it
// would make with a resting object ball, or nothing when the path misses it (or starts touching it).
std::optional<AimGeometry> plannedContact(const Vec2& from, double headingDeg, const Vec2& object,
                                          double struckRadius, double objectRadius);

// The heading (degrees in (−180, 180]) of a straight path from `from` that cuts the object ball at
// `cutDeg` to `side` (Straight or cutDeg = 0: at its centre). Nothing when the balls touch already
// (|O − C| ≤ D: there is no path to a contact) or cutDeg lies outside [0, 90).
std::optional<double> headingForCut(const Vec2& from, const Vec2& object, double struckRadius, double objectRadius,
                                    double cutDeg, CutSide side);

// The struck ball's first contact with another ball in a simulated shot: the geometry of that
// ball-ball event (the struck ball's state just before it; the aim line from where the strike found
// it). Nothing without a shot or when it touches no ball. `eventIndex` receives the event's index.
std::optional<AimGeometry> firstContact(const SimulationResult& result, int* eventIndex = nullptr,
                                        int* objectBall = nullptr);
// The geometry of ball-ball event `index` (ball 0 of the event is the "struck" one); nothing for
// another kind of event.
std::optional<AimGeometry> contactOfEvent(const SimulationResult& result, int index);

// The struck ball just after the cue strike (the shot's first event): what the cue gave it.
struct Launch {
    int ball = -1;
    double speed = 0.0;           // m/s, |v| just after the strike
    Vec2 velocity = Vec2::Zero(); // m/s
    Vec3 spin = Vec3::Zero();     // rad/s
    double topspin = 0.0;         // rad/s, the spin about the horizontal axis across the path
                                  // (+ follow, − draw): ω · (z × d)
    double sideSpin = 0.0;        // rad/s, ω_z (+ counter-clockwise from above: left english)
};
std::optional<Launch> launchOf(const SimulationResult& result);

}  // namespace cuelab::aim
