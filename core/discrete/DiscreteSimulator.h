#pragma once
// The 2011 method, kept as a teaching comparison to the exact event-based simulator.
//
// It is the discrete scheme of NeHe's OpenGL lesson 30 as the original student game used it:
// time advances in fixed steps; within a step every ball moves in a straight line; a cushion hit is
// found by the ray-plane time of impact t = N.(X - p0) / N.d, a ball-ball hit by testing the moving
// spheres at a fixed number of sub-steps; the earliest hit of the step is resolved and the rest of
// the step is played out. Cushions reflect like a mirror, R = 2(-O.N)N + O (scaled by restitution
// along N); two equal balls exchange the components of their velocities along the line of centres.
// Friction is a constant deceleration, a ball rests below a speed threshold, and there is no spin.
//
// Its known weaknesses are what it teaches: a hit between two sub-steps can be missed (tunnelling)
// or found late (overlap), times of impact are only as good as the sub-step, and the answer depends
// on the step size. The exact simulator (Simulation.h) has none of these.

#include "Setup.h"
#include "Table.h"
#include "Types.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace cuelab::discrete {

struct DiscreteSettings {
    double timeStep = 1.0 / 60.0;  // s, one frame of the original game
    int subSteps = 10;             // sphere-sphere tests per step (NeHe's lesson used a few)
    double restSpeed = 0.005;      // m/s, below this a ball is put to rest
    double maxTime = 60.0;         // s
    double friction = 0.0;         // m/s^2 constant deceleration; 0 = mu_roll * g of the setup
    bool keepFrames = true;        // false: DiscreteResult::frames stays empty (long runs at tiny steps)
};

struct DiscreteBall;

// Called with the balls at t = 0 and after every step; returning false ends the run there.
using DiscreteStepObserver = std::function<bool(double time, const std::vector<DiscreteBall>& balls)>;

enum class DiscreteEventKind : std::uint8_t { BallBall, BallCushion, BallPocket, Rest };

struct DiscreteEvent {
    DiscreteEventKind kind = DiscreteEventKind::BallBall;
    double time = 0.0;           // s, as the method finds it (sub-step resolution for ball-ball)
    int ball = -1;
    int other = -1;              // second ball (BallBall), cushion index (BallCushion), pocket (BallPocket)
    double overlap = 0.0;        // m, how far the balls had interpenetrated when the hit was found
    bool jaw = false;            // BallCushion: `other` indexes Table::jaws instead of Table::cushions
};

struct DiscreteBall {
    Vec2 position = Vec2::Zero();  // m
    Vec2 velocity = Vec2::Zero();  // m/s
    bool pocketed = false;
};

struct DiscreteResult {
    std::vector<DiscreteEvent> events;
    std::vector<double> frameTimes;                  // s
    std::vector<std::vector<DiscreteBall>> frames;   // frames[k][ball] at frameTimes[k]
    double endTime = 0.0;                            // s, all at rest or maxTime
    double maxOverlap = 0.0;                         // m, worst ball-ball interpenetration seen
};

// Runs the 2011 method on a setup. The cue strike gives the struck ball the speed of the exact
// model's level, centre-ball strike along the heading; tip offsets and spin are ignored (the
// method has none).
// `observer`, when given, sees every step (see DiscreteStepObserver).
DiscreteResult simulateDiscrete(const Setup& setup, const DiscreteSettings& settings = {},
                                const DiscreteStepObserver& observer = {});

}  // namespace cuelab::discrete
