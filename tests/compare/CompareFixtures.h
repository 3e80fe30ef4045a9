#pragma once
// Setups shared by the comparison suites.

#include "SetupFile.h"

#include <QString>
#include <QtTest>

#include <cmath>
#include <stdexcept>

namespace cuelab::testing {

inline QString examplePath(const QString& file)
{
    return QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/") + file;
}

inline Setup loadExample(const QString& file)
{
    QString error;
    const std::optional<Setup> s = io::loadSetup(examplePath(file), &error);
    if (!s) throw std::runtime_error(error.toStdString());
    return *s;
}

constexpr double kR = 0.028575;

inline Ball ballAt(const std::string& id, const Vec2& p, const Vec2& v = Vec2::Zero(), const Vec3& w = Vec3::Zero())
{
    Ball b;
    b.id = id;
    b.state.position = p;
    b.state.velocity = v;
    b.state.spin = w;
    b.state.motion = classify(b.state, b.radius);
    return b;
}

// A ball rolling along +x at `speed` on a closed 9-ft table: the one motion the exact simulator and
// both stepped engines model alike (constant deceleration mu_roll g until it stops).
inline Setup rollingBall(double speed)
{
    Setup s;
    s.table.pockets = false;
    s.physics.ballCushionModel = BallCushionModel::Mirror;
    s.balls.push_back(ballAt("cue", Vec2(0.4, 0.5), Vec2(speed, 0.0), Vec3(0.0, speed / kR, 0.0)));
    return s;
}

// A head-on hit on a frictionless cloth with perfectly elastic balls and mirror cushions: the physics
// of the 2011 method, so the difference is the method's stepping alone.
inline Setup frictionlessHeadOn(double speed, double maxTime)
{
    Setup s;
    s.table.pockets = false;
    s.physics.muSlide = 1e-9;
    s.physics.muRoll = 1e-9;
    s.physics.muSpin = 1e-9;
    s.physics.ballBallRestitution = 1.0;
    s.physics.ballCushionModel = BallCushionModel::Mirror;
    s.simulation.maxTime = maxTime;
    s.balls.push_back(ballAt("cue", Vec2(0.5, 0.6), Vec2(speed, 0.0)));
    s.balls.push_back(ballAt("1", Vec2(1.0, 0.6)));
    return s;
}

}  // namespace cuelab::testing
