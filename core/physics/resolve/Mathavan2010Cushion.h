#pragma once
// Mathavan, Jackson & Parkin 2010, "A theoretical analysis of billiard ball dynamics under cushion
// impacts", Proc. IMechE Part C 224: 1863-1873 (PHYSICS.md, "Ball-cushion models of pooltool").
//
// Two contacts act together during the impact: the cushion nose I, above the equator at
// theta = asin(h/R - 1), and the cloth C under the ball. The normal impulse P at I is the independent
// variable; as it grows by dP, Coulomb friction acts at I (mu_w = PhysicsParams::cushionFriction)
// against the slip of I, the cloth pushes up by whatever keeps the ball on the cloth (the cushion
// pushes it down by sin(theta) dP and its friction lifts or lowers it) and rubs with the cloth's
// sliding friction (mu_s = PhysicsParams::muSlide) against the slip of C. Compression lasts until I
// stops approaching; restitution then goes on until the work of the normal force returned to the ball
// is e^2 of the work of compression (the energetic coefficient, e = cushionRestitution).
//
// What is exact and what is not: the paper integrates in fixed impulse steps (explicit Euler in P),
// and so does this model, with PhysicsParams::mathavanSteps steps over the expected impulse
// (1 + e) m v_n / cos(theta). Inside a step the slip directions are those at its start. The ends of
// compression and restitution are exact for the discrete scheme: the last step is cut where the
// normal velocity reaches zero (linear in dP) and where the returned work reaches e^2 W_c (quadratic
// in dP), so the normal work of each step is exact (trapezoidal on a linear velocity). A step's
// friction never more than stops the slip of its own contact (the paper's rolling condition,
// eqs. 15a-b, without the chatter of a reversing slip). The error against the continuous model is of
// order 1/steps (tst_cushionmodels measures it). Valid to about 2.5 m/s normal speed (the paper).
//
// Guards (never reached with sane parameters, tested): a ball that does not approach gets no impulse;
// the integration stops after 8 x steps; a ball still pressing into the cushion then loses its normal
// velocity (which only removes energy).

#include "resolve/CushionModel.h"

namespace cuelab {

CushionResult mathavan2010Cushion(const CushionContact& contact, const PhysicsParams& p);

}  // namespace cuelab
