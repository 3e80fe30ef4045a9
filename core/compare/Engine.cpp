#include "Engine.h"

#include "EngineParts.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cuelab::compare {

using detail::number;

std::string_view toString(EngineKind kind)
{
    switch (kind) {
    case EngineKind::Exact: return "exact";
    case EngineKind::Discrete: return "discrete";
    case EngineKind::Box2D: return "box2d";
    }
    return "exact";
}

bool parseEngineKind(std::string_view text, EngineKind& out)
{
    for (EngineKind k : {EngineKind::Exact, EngineKind::Discrete, EngineKind::Box2D}) {
        if (toString(k) == text) {
            out = k;
            return true;
        }
    }
    return false;
}

std::string_view toString(CollisionKind kind)
{
    switch (kind) {
    case CollisionKind::BallBall: return "ball-ball";
    case CollisionKind::BallCushion: return "ball-cushion";
    case CollisionKind::BallPocket: return "ball-pocket";
    }
    return "ball-ball";
}

double defaultStep(EngineKind kind)
{
    return kind == EngineKind::Exact ? 0.0 : 1.0 / 60.0;
}

int defaultSubsteps(EngineKind kind)
{
    switch (kind) {
    case EngineKind::Exact: return 0;
    case EngineKind::Discrete: return 10;
    case EngineKind::Box2D: return 8;
    }
    return 0;
}

EngineSettings resolved(EngineSettings settings)
{
    if (settings.engine == EngineKind::Exact) {
        settings.dt = 0.0;
        settings.substeps = 0;
        return settings;
    }
    if (settings.dt == 0.0) settings.dt = defaultStep(settings.engine);
    if (settings.substeps == 0) settings.substeps = defaultSubsteps(settings.engine);
    // Samples fall on the engine's own steps: its state between two steps is not defined.
    if (std::isfinite(settings.dt) && settings.dt > 0.0 && std::isfinite(settings.sampleDt))
        settings.sampleDt = settings.dt * std::max(1.0, std::round(settings.sampleDt / settings.dt));
    return settings;
}

StepLimits stepLimits(EngineKind kind)
{
    StepLimits l;
    switch (kind) {
    case EngineKind::Exact: break;
    case EngineKind::Discrete:
        l.minDt = 1e-5;
        l.maxDt = 1.0;
        l.minSubsteps = 1;
        l.maxSubsteps = 10000;
        l.minDtReason = "a smaller step needs more than 100000 steps per simulated second, each testing every "
                        "pair of balls at every sub-step, so that a break would run for minutes; the error "
                        "at 1e-05 s is already below a micrometre";
        break;
    case EngineKind::Box2D:
        l.minDt = 1e-4;
        l.maxDt = 1.0;
        l.minSubsteps = 1;
        l.maxSubsteps = 1000;
        l.minDtReason = "Box2D computes in 32-bit floats: at smaller steps a slow ball moves less per step "
                        "than a few roundings of its position, so the run drifts by rounding instead of "
                        "converging";
        break;
    }
    return l;
}

std::optional<SettingsProblem> checkSettings(const EngineSettings& given)
{
    if (!std::isfinite(given.sampleDt) || given.sampleDt < 1e-4 || given.sampleDt > 1.0)
        return SettingsProblem{"sample_dt", "the sample step must lie between 0.0001 s and 1 s"};
    const EngineSettings s = resolved(given);
    if (s.engine == EngineKind::Exact) return std::nullopt;
    const StepLimits l = stepLimits(s.engine);
    const std::string engine(toString(s.engine));
    if (!std::isfinite(s.dt) || s.dt <= 0.0)
        return SettingsProblem{"dt", "the step must be a number of seconds > 0"};
    if (s.dt < l.minDt)
        return SettingsProblem{"dt", number(s.dt) + " s is below the smallest " + engine + " step, " +
                                         number(l.minDt) + " s: " + l.minDtReason};
    if (s.dt > l.maxDt)
        return SettingsProblem{"dt", number(s.dt) + " s is above the largest " + engine + " step, " +
                                         number(l.maxDt) + " s"};
    const std::string what = s.engine == EngineKind::Box2D ? "velocity iterations" : "sub-steps";
    if (s.substeps < l.minSubsteps)
        return SettingsProblem{"substeps", "the " + what + " must be at least " + std::to_string(l.minSubsteps)};
    if (s.substeps > l.maxSubsteps)
        return SettingsProblem{"substeps", "the " + what + " must be at most " + std::to_string(l.maxSubsteps)};
    if (s.engine == EngineKind::Box2D) {
        if (s.positionIterations < 0 || s.positionIterations > 1000)
            return SettingsProblem{"position_iterations", "must lie between 0 and 1000"};
        if (!std::isfinite(s.lengthScale) || s.lengthScale < 0.1 || s.lengthScale > 1000.0)
            return SettingsProblem{"length_scale", "must lie between 0.1 and 1000 Box2D units per metre"};
        if (!std::isfinite(s.restitutionThreshold) || s.restitutionThreshold < 0.0)
            return SettingsProblem{"restitution_threshold", "must be a speed >= 0 m/s"};
    }
    return std::nullopt;
}

EngineRun runEngine(const Setup& setup, const EngineSettings& given, const Progress& progress)
{
    if (const auto problem = checkSettings(given)) throw std::invalid_argument(problem->setting + ": " + problem->message);
    const EngineSettings s = resolved(given);
    switch (s.engine) {
    case EngineKind::Exact: return detail::runExact(setup, s, progress);
    case EngineKind::Discrete: return detail::runDiscrete(setup, s, progress);
    case EngineKind::Box2D: return detail::runBox2D(setup, s, progress);
    }
    return detail::runExact(setup, s, progress);
}

std::vector<std::string> unsupportedFeatures(const Setup& setup, EngineKind kind)
{
    std::vector<std::string> out;
    if (kind == EngineKind::Exact) return out;
    const bool discrete = kind == EngineKind::Discrete;
    const std::string name = discrete ? "the discrete method" : "Box2D";
    if (setup.shot) {
        const CueStrike& shot = *setup.shot;
        const std::string speedNote =
            discrete ? " (the ball leaves at the centre-ball speed)" : " (the ball keeps the strike's speed)";
        if (shot.side != 0.0)
            out.push_back("shot.side " + number(shot.side) + ": " + name + " has no spin, the english is lost" +
                          speedNote);
        if (shot.height != 0.0)
            out.push_back("shot.height " + number(shot.height) + ": " + name + " has no spin, the " +
                          (shot.height < 0 ? "draw" : "follow") + " is lost" + speedNote);
        if (shot.elevationDeg != 0.0)
            out.push_back("shot.elevation " + number(shot.elevationDeg) + ": " + name +
                          " takes the cue as level (no jump, no masse, no swerve)");
    }
    bool moving = setup.shot.has_value();
    for (const Ball& b : setup.balls) {
        if (b.state.spin != Vec3::Zero())
            out.push_back("balls." + b.id + ".spin: " + name + " has no spin, it is ignored");
        if (b.state.velocity != Vec2::Zero()) moving = true;
        // Both engines move discs in the table's plane: a height or a vertical speed has no place there.
        if (b.state.z != 0.0 || b.state.vz != 0.0)
            out.push_back("balls." + b.id + ".z " + number(b.state.z) + ", vz " + number(b.state.vz) + ": " + name +
                          " cannot fly, the ball starts on the cloth (no flight, no bounce, no jump over a ball)");
    }
    const PhysicsParams& p = setup.physics;
    if (moving)
        out.push_back("no slide phase: " + name + " slows every ball by the rolling resistance mu_roll g = " +
                      number(p.muRoll * p.gravity) +
                      " m/s^2 at all times, where a struck or hit ball first slides at mu_slide g until it "
                      "rolls (a centre-ball stroke then keeps 5/7 of its speed)");
    if (p.ballBallModel == BallBallModel::Frictional)
        out.push_back("physics.ball_ball.model frictional: " + name + " has frictionless ball contacts (no throw)");
    if (p.ballCushionModel != BallCushionModel::Mirror)
        out.push_back("physics.ball_cushion.model " + std::string(toString(p.ballCushionModel)) + ": " + name +
                      " reflects off cushions like a mirror with restitution " + number(p.cushionRestitution) +
                      " (no cushion friction, no spin change)");
    if (discrete) {
        if (p.ballBallRestitution != 1.0)
            out.push_back("physics.ball_ball.restitution " + number(p.ballBallRestitution) +
                          ": the discrete method's exchange is perfectly elastic (restitution 1)");
        for (const Ball& b : setup.balls) {
            if (b.mass != setup.balls.front().mass) {
                out.push_back("balls." + b.id + ".mass: the discrete method's exchange assumes equal masses");
                break;
            }
        }
    }
    return out;
}

}  // namespace cuelab::compare
