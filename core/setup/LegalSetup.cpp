#include "LegalSetup.h"

#include "LegalGame.h"
#include "LegalGeometry.h"
#include "resolve/CushionModel.h"

#include <cmath>
#include <cstdio>
#include <set>

namespace cuelab {

using legal::ballPath;
using legal::quoted;

namespace {

// Collects problems; with `firstOnly` it stops taking them after the first (the rules still run,
// but they are cheap: no geometry is computed once one is found).
class Problems {
public:
    explicit Problems(bool firstOnly) : firstOnly_(firstOnly) {}

    bool done() const { return firstOnly_ && !list_.empty(); }
    void add(SetupProblem p)
    {
        if (!done()) list_.push_back(std::move(p));
    }
    void add(std::optional<SetupProblem> p)
    {
        if (p) add(std::move(*p));
    }
    std::vector<SetupProblem> take() { return std::move(list_); }

    // The value rules. Each returns whether the value passed, so that dependent rules can be skipped.
    // A ball's values name the ball and the field: "ball \"cue\": radius must be greater than 0".
    bool finite(double x, const std::string& path, const Ball* ball = nullptr, int index = -1)
    {
        if (std::isfinite(x)) return true;
        add(make(path, ball, index, "must be a finite number (found " + describeNumber(x) + ")"));
        return false;
    }
    bool positive(double x, const std::string& path, const Ball* ball = nullptr, int index = -1)
    {
        if (!finite(x, path, ball, index)) return false;
        if (x > 0.0) return true;
        add(make(path, ball, index, "must be greater than 0 (found " + describeNumber(x) + ")"));
        return false;
    }
    bool nonNegative(double x, const std::string& path)
    {
        if (!finite(x, path)) return false;
        if (x >= 0.0) return true;
        add(make(path, nullptr, -1, "must not be negative (found " + describeNumber(x) + ")"));
        return false;
    }
    bool unitInterval(double x, const std::string& path)
    {
        if (!finite(x, path)) return false;
        if (x >= 0.0 && x <= 1.0) return true;
        add(make(path, nullptr, -1, "must lie between 0 and 1 (found " + describeNumber(x) + ")"));
        return false;
    }
    // x (a finite value, or a magnitude computed from finite values) must not exceed `max` (`unit`
    // names its unit in the message: " m/s").
    bool atMost(double x, double max, const char* unit, const std::string& path, const Ball* ball = nullptr, int index = -1)
    {
        if (x <= max) return true;
        add(make(path, ball, index,
                 "must be at most " + describeNumber(max) + unit + " (found " + describeNumber(x) + unit + ")"));
        return false;
    }
    // positive() and at most `max`.
    bool positiveUpTo(double x, double max, const char* unit, const std::string& path, const Ball* ball = nullptr, int index = -1)
    {
        return positive(x, path, ball, index) && atMost(x, max, unit, path, ball, index);
    }
    // nonNegative() and at most `max`.
    bool nonNegativeUpTo(double x, double max, const char* unit, const std::string& path)
    {
        return nonNegative(x, path) && atMost(x, max, unit, path);
    }
    template <int N>
    bool finiteVector(const Eigen::Matrix<double, N, 1>& v, const std::string& path, const Ball& ball, int index)
    {
        bool ok = true;
        for (int i = 0; i < N; ++i)
            ok = finite(v[i], path + "[" + std::to_string(i) + "]", &ball, index) && ok;
        return ok;
    }

    static SetupProblem make(const std::string& path, const Ball* ball, int index, const std::string& what)
    {
        if (!ball) return SetupProblem{path, {}, -1, what};
        // "balls[2].position[1]" -> "ball \"7\": position[1] must be ..."
        const std::size_t dot = path.find("].");
        const std::string field = dot == std::string::npos ? path : path.substr(dot + 2);
        return SetupProblem{path, ball->id, index, "ball " + quoted(ball->id) + ": " + field + " " + what};
    }

private:
    bool firstOnly_;
    std::vector<SetupProblem> list_;
};

void checkTableSpec(const TableSpec& spec, Problems& out)
{
    if (spec.length) out.positiveUpTo(*spec.length, SetupBounds::tableSize, " m", "table.length");
    if (spec.width) out.positiveUpTo(*spec.width, SetupBounds::tableSize, " m", "table.width");
    if (spec.cushionHeight) out.positiveUpTo(*spec.cushionHeight, SetupBounds::cushionHeight, " m", "table.cushion_height");
}

void checkPhysics(const PhysicsParams& p, Problems& out)
{
    out.positiveUpTo(p.gravity, SetupBounds::gravity, " m/s²", "physics.gravity");
    // The cloth frictions must be positive: with zero friction a ball would slide, roll or spin for
    // ever and every transition time (|u| / (mu g), ...) would divide by zero.
    out.positiveUpTo(p.muSlide, SetupBounds::friction, "", "physics.mu_slide");
    out.positiveUpTo(p.muRoll, SetupBounds::friction, "", "physics.mu_roll");
    out.positiveUpTo(p.muSpin, SetupBounds::friction, "", "physics.mu_spin");
    out.unitInterval(p.ballBallRestitution, "physics.ball_ball.restitution");
    if (p.ballBallFrictionKind == BallBallFriction::Fixed)
        out.nonNegativeUpTo(p.ballBallFriction, SetupBounds::friction, "", "physics.ball_ball.friction");
    out.unitInterval(p.cushionRestitution, "physics.ball_cushion.restitution");
    out.nonNegativeUpTo(p.cushionFriction, SetupBounds::friction, "", "physics.ball_cushion.friction");
    out.unitInterval(p.tableRestitution, "physics.ball_table.restitution");
    out.nonNegativeUpTo(p.tableFriction, SetupBounds::friction, "", "physics.ball_table.friction");
    // The chosen cushion model's own parameters, with the ranges its registry entry gives.
    for (const CushionModelParameter& q : cushionModel(p.ballCushionModel).parameters) {
        const std::string path = "physics.ball_cushion." + std::string(q.key);
        const double x = p.*(q.field);
        if (!out.finite(x, path)) continue;
        const bool low = q.minExclusive ? !(x > q.min) : !(x >= q.min);
        const bool high = q.maxExclusive ? !(x < q.max) : !(x <= q.max);
        if (low || high)
            out.add(SetupProblem{path, {}, -1,
                                 "must lie between " + describeNumber(q.min) + " and " + describeNumber(q.max) +
                                     (q.minExclusive || q.maxExclusive ? ", bounds excluded" : "") + " (found " +
                                     describeNumber(x) + ")"});
        else if (q.integer && std::floor(x) != x)
            out.add(SetupProblem{path, {}, -1, "must be a whole number (found " + describeNumber(x) + ")"});
    }
}

// The values of ball `i`; returns whether its place can be checked (finite position, usable radius).
bool checkBallValues(const Setup& setup, std::size_t i, Problems& out)
{
    const Ball& ball = setup.balls[i];
    const int index = static_cast<int>(i);
    if (ball.id.empty()) out.add(SetupProblem{ballPath(index, "id"), {}, index, "the id must not be empty"});
    for (std::size_t j = 0; j < i && !ball.id.empty(); ++j)
        if (setup.balls[j].id == ball.id) {
            out.add(SetupProblem{ballPath(index, "id"), ball.id, index,
                                 "duplicate id " + quoted(ball.id) + " (balls[" + std::to_string(j) + "] has it too)"});
            break;
        }
    const bool placed = out.finiteVector<2>(ball.state.position, ballPath(index, "position"), ball, index);
    if (out.finiteVector<2>(ball.state.velocity, ballPath(index, "velocity"), ball, index))
        out.atMost(std::hypot(ball.state.velocity.x(), ball.state.velocity.y()), SetupBounds::speed, " m/s", ballPath(index, "velocity"), &ball, index);
    if (out.finiteVector<3>(ball.state.spin, ballPath(index, "spin"), ball, index))
        out.atMost(std::hypot(ball.state.spin.x(), ball.state.spin.y(), ball.state.spin.z()), SetupBounds::spin, " rad/s", ballPath(index, "spin"), &ball, index);
    // A ball may start in the air, never under the cloth (CONTRACT.md "Airborne balls").
    if (out.finite(ball.state.z, ballPath(index, "z"), &ball, index)) {
        if (ball.state.z < 0.0)
            out.add(SetupProblem{ballPath(index, "z"), ball.id, index, "must not be negative (found " + describeNumber(ball.state.z) + ")"});
        else
            out.atMost(ball.state.z, SetupBounds::tableSize, " m", ballPath(index, "z"), &ball, index);
    }
    if (out.finite(ball.state.vz, ballPath(index, "vz"), &ball, index))
        out.atMost(std::abs(ball.state.vz), SetupBounds::speed, " m/s", ballPath(index, "vz"), &ball, index);
    const bool sized = out.positiveUpTo(ball.radius, SetupBounds::radius, " m", ballPath(index, "radius"), &ball, index);
    out.positiveUpTo(ball.mass, SetupBounds::mass, " kg", ballPath(index, "mass"), &ball, index);
    return placed && sized;
}

void checkShot(const Setup& setup, Problems& out)
{
    if (!setup.shot) return;
    const CueStrike& shot = *setup.shot;
    bool found = false;
    for (const Ball& b : setup.balls) found = found || b.id == shot.ball;
    if (!found) out.add(SetupProblem{"shot.ball", {}, -1, "there is no ball " + quoted(shot.ball)});
    out.nonNegativeUpTo(shot.speed, SetupBounds::speed, " m/s", "shot.speed");
    if (out.finite(shot.headingDeg, "shot.heading") && std::abs(shot.headingDeg) > SetupBounds::heading)
        out.add(SetupProblem{"shot.heading", {}, -1,
                             "must lie between -" + describeNumber(SetupBounds::heading) + " and " +
                                 describeNumber(SetupBounds::heading) + " degrees (found " + describeNumber(shot.headingDeg) + ")"});
    if (out.finite(shot.elevationDeg, "shot.elevation") && (shot.elevationDeg < 0.0 || shot.elevationDeg > 90.0))
        out.add(SetupProblem{"shot.elevation", {}, -1,
                             "must lie between 0 and 90 degrees (found " + describeNumber(shot.elevationDeg) + ")"});
    const bool side = out.finite(shot.side, "shot.side");
    const bool height = out.finite(shot.height, "shot.height");
    // The tip must meet the ball: the offset from the centre is less than one radius.
    if (side && height && std::hypot(shot.side, shot.height) >= 1.0)
        out.add(SetupProblem{std::abs(shot.side) >= std::abs(shot.height) ? "shot.side" : "shot.height", {}, -1,
                             "the tip misses the ball: side and height must satisfy side² + height² < 1"});
    const bool cue = out.positiveUpTo(shot.cueMass, SetupBounds::cueMass, " kg", "shot.cue_mass");
    // 0 means no squirt (the key absent); a file that gives the tip's end mass gives a positive one,
    // a part of the cue's mass.
    if (out.nonNegative(shot.endMass, "shot.end_mass") && cue && shot.endMass > shot.cueMass)
        out.add(SetupProblem{"shot.end_mass", {}, -1,
                             "must not exceed the cue's mass of " + describeNumber(shot.cueMass) + " kg (found " +
                                 describeNumber(shot.endMass) + " kg)"});
}

void checkSimulation(const SimulationSettings& s, Problems& out)
{
    out.positiveUpTo(s.frameDt, SetupBounds::frameDt, " s", "simulation.frame_dt");
    out.positiveUpTo(s.maxTime, SetupBounds::maxTime, " s", "simulation.max_time");
}

std::vector<SetupProblem> run(const Setup& setup, bool firstOnly)
{
    Problems out(firstOnly);
    checkTableSpec(setup.table, out);
    checkPhysics(setup.physics, out);
    std::vector<bool> placeable(setup.balls.size());
    for (std::size_t i = 0; i < setup.balls.size(); ++i) placeable[i] = checkBallValues(setup, i, out);
    checkShot(setup, out);
    checkSimulation(setup.simulation, out);
    for (SetupProblem& p : gameProblems(setup)) out.add(std::move(p));
    if (out.done() || !legal::tableSpecUsable(setup.table)) return out.take();

    const Table table = makeTable(setup.table);
    out.add(legal::railsProblem(table));
    for (std::size_t i = 0; i < setup.balls.size() && !out.done(); ++i) {
        if (!placeable[i]) continue;
        const int index = static_cast<int>(i);
        out.add(legal::tableProblem(table, setup.balls[i], index));
        for (std::size_t j = 0; j < i && !out.done(); ++j)
            if (placeable[j]) out.add(legal::overlapProblem(setup.balls[i], index, setup.balls[j]));
    }
    return out.take();
}

}  // namespace

std::vector<SetupProblem> validateSetup(const Setup& setup) { return run(setup, false); }

std::optional<SetupProblem> firstSetupProblem(const Setup& setup)
{
    std::vector<SetupProblem> problems = run(setup, true);
    if (problems.empty()) return std::nullopt;
    return std::move(problems.front());
}

std::vector<SetupProblem> validateBall(const Setup& setup, std::size_t index)
{
    if (index >= setup.balls.size()) return {};
    Problems out(false);
    const bool placeable = checkBallValues(setup, index, out);
    const Ball& ball = setup.balls[index];
    const int i = static_cast<int>(index);
    // A later ball with the same id is this ball's problem too, when this is the one being edited.
    for (std::size_t j = index + 1; j < setup.balls.size() && !ball.id.empty(); ++j)
        if (setup.balls[j].id == ball.id) {
            out.add(SetupProblem{ballPath(i, "id"), ball.id, i,
                                 "duplicate id " + quoted(ball.id) + " (balls[" + std::to_string(j) + "] has it too)"});
            break;
        }
    if (!placeable || !legal::tableSpecUsable(setup.table)) return out.take();
    const Table table = makeTable(setup.table);
    out.add(legal::tableProblem(table, ball, i));
    for (std::size_t j = 0; j < setup.balls.size(); ++j) {
        if (j == index) continue;
        const Ball& other = setup.balls[j];
        if (!other.state.position.allFinite() || !std::isfinite(other.radius)) continue;
        out.add(legal::overlapProblem(ball, i, other));
    }
    return out.take();
}

std::string describeLength(double metres)
{
    const double magnitude = std::abs(metres);
    char text[64];
    if (magnitude >= 0.1) std::snprintf(text, sizeof text, "%.3f m", metres);
    else if (magnitude >= 1e-4) std::snprintf(text, sizeof text, "%.1f mm", metres * 1e3);
    else if (magnitude >= 1e-7) std::snprintf(text, sizeof text, "%.1f µm", metres * 1e6);
    else std::snprintf(text, sizeof text, "%.1f nm", metres * 1e9);
    return text;
}

std::string describeNumber(double value)
{
    char text[64];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

}  // namespace cuelab
