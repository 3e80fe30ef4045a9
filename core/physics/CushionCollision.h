#pragma once
// Ball-cushion collision, for a straight cushion nose or a jaw tip (PHYSICS.md, "Ball-cushion").
// The models themselves live in resolve/, one file each, chosen through resolve/CushionModel.h.

#include "Ball.h"
#include "Parameters.h"
#include "Types.h"
#include "resolve/CushionModel.h"
#include "resolve/Han2005Cushion.h"
#include "resolve/MirrorCushion.h"

namespace cuelab {

// `normal` is the unit normal of the cushion at the contact, pointing from the cushion to the ball's
// centre (a segment's normal; for a jaw tip, from the jaw's centre to the ball's). `noseHeight` is
// the height of the contact line above the cloth (m). Resolves with the model p.ballCushionModel
// (cushionModel(p.ballCushionModel).resolve).
CushionResult resolveCushion(const BallState& before, const Vec2& normal, double radius, double mass,
                             double noseHeight, const PhysicsParams& p);

}  // namespace cuelab
