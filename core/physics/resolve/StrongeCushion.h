#pragma once
// Stronge's compliant frictional impact (W. J. Stronge, "Impact Mechanics", Cambridge 2000/2018,
// ch. 5; pooltool's `stronge_compliant`, PR #240, PHYSICS.md). The cushion and the ball meet through
// two massless springs at the contact point: a normal one (frequency omega_n, unloading stiffer by 1/e^2
// so that the normal velocity comes back at e times the approach: e = cushionRestitution) and a
// tangential one (frequency omega_t, omega_t / omega_n = PhysicsParams::strongeOmegaRatio). While the
// tangential spring force stays below mu F_n (mu = cushionFriction) the contact sticks and the spring
// oscillates; otherwise it slips, with the force mu F_n against the slip. So a ball can slip, stick,
// and even have the friction reverse during one impact, as measured for real balls (Cross 2002).
//
// As in pooltool, the contact is at the ball's equator (the line of centres is level), the normal is
// the cushion's, the tangential motion stays along the direction of the contact's initial slip (which
// may have a vertical part from top or back spin; the vertical velocity it gives the ball is taken by
// the cloth), and the effective-mass coefficients of a solid sphere on a half-space are beta_n = 1,
// beta_t = 1 + m R^2 / I = 7/2.
//
// What is exact and what is not: every phase (compression, restitution, stick, slip) is in closed form
// (sines and cosines of time); the times at which stick turns into slip and back are roots of those
// closed forms, located by sampling each phase at 256 points and bisecting to double precision, so a
// stick shorter than 1/256 of the impact could be missed. Energy cannot rise: the final tangential
// contact speed is at most the initial one (a rounding guard keeps it so), the normal one is e times
// the approach, and the vertical part is discarded. A ball that does not approach gets no impulse.

#include "resolve/CushionModel.h"

#include <vector>

namespace cuelab {

CushionResult strongeCushion(const CushionContact& contact, const PhysicsParams& p);

// One phase of the tangential contact: sticking or slipping from `start` (in 1/omega_n), with the
// contact's tangential velocity v0 (m/s) then.
struct StrongePhase {
    bool stick = false;
    double start = 0.0;
    double v0 = 0.0;
};

// What happened inside one impact, for Explain: every phase in order, and whether the contact
// chattered past the switch limit (it then finishes slipping).
struct StrongeTrace {
    std::vector<StrongePhase> phases;
    bool chattered = false;
};

// The one-dimensional problem underneath, in units of the contact's velocities: approach vn0 < 0
// (normal velocity of the contact point, positive away from the cushion), initial tangential slip
// vt0 >= 0. Returns the final tangential velocity of the contact point (the normal one is -e vn0).
// With `trace`, records the phases too (the arithmetic is the same with or without it).
double strongeTangentialVelocity(double vn0, double vt0, double mu, double e, double omegaRatio,
                                 double betaT = 3.5, double betaN = 1.0, StrongeTrace* trace = nullptr);

}  // namespace cuelab
