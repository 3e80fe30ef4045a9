#pragma once
// Two teaching views of a collision (issue 22): the centre-of-mass frame of the event's balls, and
// the kinetic energy split into its parts and its losses.
//
// Centre-of-mass frame. The pair's centre of mass moves at V = Σ m_i v_i / Σ m_i; seen from a frame
// moving with it, ball i has the momentum p*_i = m_i (v_i − V), and Σ p*_i = Σ m_i v_i − M V = 0: the
// momenta are equal and opposite. A collision between the two balls only exchanges an impulse J
// (J on one, −J on the other), so the total stays zero after it; an elastic, frictionless collision
// keeps |p*_i| too and only turns the pair of momenta (Landau & Lifshitz, Mechanics §17). The frame
// is the one of the velocities before the event, for before and after alike: an inertial frame.
//
// Energy parts. For each ball of the event: its translational (½ m |v|²) and rotational (½ I |ω|²)
// energy just after the event, what the event itself took (the energy just before minus just after;
// negative for a ball that gained, as an object ball does), and what the cloth took since the ball's
// previous event (the energy just after that event, or as set up, minus the energy just before this
// one). The four add up to the energy the ball had after its previous event.

#include "Simulation.h"
#include "Types.h"

#include <vector>

namespace cuelab::aim {

struct FrameBody {
    double mass = 0.0;           // kg
    Vec2 velocityBefore = Vec2::Zero();  // m/s, table frame
    Vec2 velocityAfter = Vec2::Zero();
};

struct CentreOfMassFrame {
    Vec2 velocity = Vec2::Zero();            // m/s, V of the pair before the event
    std::vector<Vec2> momentaBefore;         // N s, p*_i = m_i (v_i − V), per body
    std::vector<Vec2> momentaAfter;          // N s, p*′_i = m_i (v′_i − V)
    Vec2 totalBefore() const;                // Σ p*_i (0 up to rounding)
    Vec2 totalAfter() const;
};

CentreOfMassFrame centreOfMassFrame(const std::vector<FrameBody>& bodies);
// The bodies of event `index` of a simulation (its one or two balls).
std::vector<FrameBody> frameBodies(const SimulationResult& result, int index);

struct BallEnergy {
    int ball = -1;
    double translation = 0.0;      // J, just after the event
    double rotation = 0.0;         // J, just after the event
    double translationBefore = 0.0;  // J, just before the event
    double rotationBefore = 0.0;     // J
    double lostToEvent = 0.0;      // J, just before − just after (negative: the ball gained)
    double lostToCloth = 0.0;      // J, since the ball's previous event (>= 0: the cloth only takes)
    double previous = 0.0;         // J, just after the ball's previous event (or as set up), + m g (z_prev - z) if it flew
    double after() const { return translation + rotation; }
    double before() const { return translationBefore + rotationBefore; }
};

struct EnergyParts {
    std::vector<BallEnergy> balls;  // the event's balls, in the event's order
    double translation = 0.0, rotation = 0.0, lostToEvent = 0.0, lostToCloth = 0.0, previous = 0.0;  // J, sums
};

EnergyParts energyParts(const SimulationResult& result, int index);

}  // namespace cuelab::aim
