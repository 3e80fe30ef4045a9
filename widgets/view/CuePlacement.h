#pragma once
// Where the cue stick is drawn before the shot: behind the struck ball along the heading, its tip
// 2 cm from the contact point given by the shot's side and height offsets, the butt raised by the
// shot's elevation. The stick is never drawn through a ball: when another ball lies in its way, the
// drawing raises the butt (as a player cues over a ball) to the lowest elevation that clears every
// ball, and if even a near-vertical cue does not clear, it draws a shorter stick. This changes only
// the picture, never the shot. No GL.

#include "CueStrike.h"
#include "Simulation.h"

#include <QMatrix4x4>

#include <optional>
#include <vector>

namespace cuelab {

struct CuePose {
    QMatrix4x4 model;            // the stick mesh (along +x from its tip) into the table frame
    double elevationDeg = 0.0;   // as drawn (>= the shot's when raised)
    double length = 0.0;         // m, as drawn (kCueLength unless shortened)
    bool raised = false;         // the drawn elevation differs from the shot's
};

// Where the cue tip meets `ball` (its setup place, centre at z = R): on its surface, facing the cue, offset
// by the shot's side (to the player's right) and height (up), each clamped to ±0.9 R. The table view
// draws its tip mark there and drags it (AimDrag).
Vec3 tipContactPoint(const Ball& ball, const CueStrike& shot);

// nullopt when the shot names no ball of the result. `balls` are where the balls stand (the setup);
// pocketed ones are ignored.
std::optional<CuePose> cuePose(const SimulationResult& result, const std::vector<Ball>& balls, const CueStrike& shot);

// m: the stick's radius `along` metres from its tip (tapering from 6.5 mm at the tip to 14.5 mm at
// the butt, as CueStickMesh draws it).
double cueStickRadius(double along);

// Whether a stick from `tip` along the unit `along` over `length` metres keeps clear of every ball
// but `struck` (the stick's radius tapering from tip to butt, plus a hair).
bool cueClearsBalls(const std::vector<Ball>& balls, int struck, const Vec3& tip, const Vec3& along, double length);

}  // namespace cuelab
