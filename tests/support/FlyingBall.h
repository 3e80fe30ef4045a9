#pragma once
// A ball already off the cloth, for the tests of flight (issue 23): at (x, y), its centre z above its
// resting height, moving up at vz (negative: down) and across at v.

#include "Ball.h"
#include "Flight.h"
#include "Simulation.h"

#include <string>

inline cuelab::Ball flyingBall(const std::string& id, double x, double y, double z, double vz,
                               const cuelab::Vec2& v = cuelab::Vec2::Zero())
{
    cuelab::Ball b;
    b.id = id;
    b.state.position = cuelab::Vec2(x, y);
    b.state.velocity = v;
    b.state.z = z;
    b.state.vz = vz;
    b.state.motion = cuelab::MotionState::Airborne;
    return b;
}

// The mechanical energy of every ball of the run at t (kinetic, with vz, plus m g z), J.
inline double mechanicalEnergyAt(const cuelab::SimulationResult& r, double t)
{
    double e = 0.0;
    const std::vector<cuelab::BallState> s = r.statesAt(t);
    for (std::size_t i = 0; i < s.size(); ++i)
        e += cuelab::mechanicalEnergy(s[i], r.balls[i].radius, r.balls[i].mass, r.physics.gravity);
    return e;
}
