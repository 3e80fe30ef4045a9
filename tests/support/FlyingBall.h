#pragma once
// A ball already off the cloth, for the tests of flight (issue 23): at (x, y), its centre z above its
// resting height, moving up at vz (negative: down) and across at v.

#include "Ball.h"
#include "Flight.h"
#include "Motion.h"
#include "Setup.h"
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

// seed14-shot161368 late in its run: ball "top" (pool ball, flying) rests on ball "low", 67 degrees up
// its side, and comes down on it at a micrometre a second while low rolls on at 0.2 m/s. The
// simulator holds the pair from its first event (the air hold; tst_airhold, tst_explain).
inline cuelab::Setup comingDownOnARollingBall()
{
    using namespace cuelab;
    const double R = 0.028575;  // m (the pool table's ball)
    Setup s;
    s.physics.ballBallModel = BallBallModel::Frictional;
    s.physics.ballBallRestitution = 0.8696339351623968;
    s.physics.ballBallFrictionKind = BallBallFriction::Alciatore;
    Ball low;
    low.id = "low";
    low.state.position = Vec2(0.55797045382499333, 0.3201902311557831);
    low.state.velocity = Vec2(-0.18728457527418221, 0.064693595031395629);
    low.state.spin = Vec3(-low.state.velocity.y() / R, low.state.velocity.x() / R, 0.0931026);  // rolling
    Ball top;
    top.id = "top";
    top.state.position = Vec2(0.5801230826325765, 0.31698493365925795);
    top.state.z = 0.052584309515991051;
    top.state.velocity = Vec2(-0.16430699696696116, 0.16876048016763104);
    top.state.vz = -0.0033365180679032478;
    top.state.spin = Vec3(127.296, 27.9377, -31.354);
    s.balls = {low, top};
    for (Ball& b : s.balls) b.state.motion = isAirborne(b.state) ? MotionState::Airborne : classify(b.state, b.radius);
    return s;
}
