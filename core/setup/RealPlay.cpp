#include "RealPlay.h"

#include "LegalGeometry.h"

#include <cmath>

namespace cuelab {

namespace {

class Warnings {
public:
    // `x` above `realPlay` but within `bound` (so finite and legal as far as this rule goes).
    void check(double x, double realPlay, double bound, const char* unit, const std::string& path,
               const Ball* ball = nullptr, int index = -1)
    {
        if (!(x > realPlay && x <= bound)) return;
        std::string what = describeNumber(x) + unit + " is beyond real play (up to " + describeNumber(realPlay) + unit +
                           "); it loads and simulates as given";
        if (!ball) {
            list_.push_back(SetupWarning{path, {}, -1, what});
            return;
        }
        // "balls[0].velocity" -> "ball \"cue\": velocity 40 m/s is beyond ..."
        const std::size_t dot = path.find("].");
        const std::string field = dot == std::string::npos ? path : path.substr(dot + 2);
        list_.push_back(SetupWarning{path, ball->id, index, "ball " + legal::quoted(ball->id) + ": " + field + " " + what});
    }
    std::vector<SetupWarning> take() { return std::move(list_); }

private:
    std::vector<SetupWarning> list_;
};

}  // namespace

std::vector<SetupWarning> setupWarnings(const Setup& setup)
{
    Warnings out;
    const TableSpec& t = setup.table;
    if (t.length) out.check(*t.length, RealPlay::tableSize, SetupBounds::tableSize, " m", "table.length");
    if (t.width) out.check(*t.width, RealPlay::tableSize, SetupBounds::tableSize, " m", "table.width");
    if (t.cushionHeight)
        out.check(*t.cushionHeight, RealPlay::cushionHeight, SetupBounds::cushionHeight, " m", "table.cushion_height");

    const PhysicsParams& p = setup.physics;
    out.check(p.gravity, RealPlay::gravity, SetupBounds::gravity, " m/s²", "physics.gravity");
    out.check(p.muSlide, RealPlay::friction, SetupBounds::friction, "", "physics.mu_slide");
    out.check(p.muRoll, RealPlay::friction, SetupBounds::friction, "", "physics.mu_roll");
    out.check(p.muSpin, RealPlay::friction, SetupBounds::friction, "", "physics.mu_spin");
    if (p.ballBallFrictionKind == BallBallFriction::Fixed)
        out.check(p.ballBallFriction, RealPlay::friction, SetupBounds::friction, "", "physics.ball_ball.friction");
    out.check(p.cushionFriction, RealPlay::friction, SetupBounds::friction, "", "physics.ball_cushion.friction");

    for (std::size_t i = 0; i < setup.balls.size(); ++i) {
        const Ball& b = setup.balls[i];
        const int index = static_cast<int>(i);
        const BallState& s = b.state;
        out.check(std::hypot(s.velocity.x(), s.velocity.y()), RealPlay::speed, SetupBounds::speed, " m/s",
                  legal::ballPath(index, "velocity"), &b, index);
        out.check(std::hypot(s.spin.x(), s.spin.y(), s.spin.z()), RealPlay::spin, SetupBounds::spin, " rad/s",
                  legal::ballPath(index, "spin"), &b, index);
        out.check(b.radius, RealPlay::radius, SetupBounds::radius, " m", legal::ballPath(index, "radius"), &b, index);
        out.check(b.mass, RealPlay::mass, SetupBounds::mass, " kg", legal::ballPath(index, "mass"), &b, index);
    }

    if (setup.shot) {
        const CueStrike& shot = *setup.shot;
        out.check(shot.speed, RealPlay::speed, SetupBounds::speed, " m/s", "shot.speed");
        out.check(std::abs(shot.headingDeg), RealPlay::heading, SetupBounds::heading, "°", "shot.heading");
        out.check(shot.cueMass, RealPlay::cueMass, SetupBounds::cueMass, " kg", "shot.cue_mass");
    }

    out.check(setup.simulation.frameDt, RealPlay::frameDt, SetupBounds::frameDt, " s", "simulation.frame_dt");
    out.check(setup.simulation.maxTime, RealPlay::maxTime, SetupBounds::maxTime, " s", "simulation.max_time");
    return out.take();
}

}  // namespace cuelab
