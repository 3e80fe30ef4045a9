#pragma once
// Seed headings from the aiming geometry. For an object ball O to travel towards a target point T
// (a pocket's centre), the struck ball must meet it at the ghost ball G = O − D (T − O)/|T − O|, D
// the touch distance of the two balls (BallContact.h); aiming the struck ball's centre at G is the
// ghost-ball aim (Aim.h reads the same geometry off a contact).
//   direct       the struck ball goes straight to G;
//   bank         O goes to T mirrored over one or two cushion lines (the lines its centre runs along
//                when it touches a cushion, one radius off the nose): reflecting the target is
//                reflecting the path (the angle of incidence is the angle of reflection; spin and
//                cushion friction bend real banks, which the refinement corrects);
//   kick         the struck ball goes to G mirrored over one or two cushion lines;
//   combination  the struck ball sends another ball A to O's ghost ball, which sends O to T.
// A goal without a ball to pot (position only, first contact) gets aims at every object ball's
// centre and cut a quarter and a half ball either side, and the direct line to each zone's centre.

#include "Goal.h"
#include "Setup.h"

#include <string>
#include <vector>

namespace cuelab::solve {

enum class SeedKind { Direct, Bank, Kick, Combination, Position };

struct Seed {
    double headingDeg = 0.0;  // in (−180, 180]
    SeedKind kind = SeedKind::Direct;
    int cushions = 0;         // mirrors used (banks and kicks)
    std::string label;        // for people and tests: "1 → pocket-tr, bank over rail-t"
};

// Every seed of the setup's strike for the goal, duplicates (headings within 1e-9°) removed, in a
// fixed order (targets in the goal's order, then pockets by index, then direct, banks, kicks,
// combinations).
std::vector<Seed> geometricSeeds(const Setup& setup, const analysis::Goal& goal);

}  // namespace cuelab::solve
