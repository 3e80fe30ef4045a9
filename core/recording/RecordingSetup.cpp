#include "RecordingSetup.h"

#include "KindDefaults.h"
#include "LegalPlacement.h"
#include "LegalSetup.h"
#include "Simulation.h"

#include <cmath>
#include <numbers>

namespace cuelab {

namespace {

// The ball speed right after a centre strike at 1 m/s of `shot`'s cue (elevation 0, no tip offset).
double ballSpeedPerCueSpeed(const Setup& setup, const std::string& id)
{
    Setup probe = setup;
    CueStrike strike = setup.shot.value_or(CueStrike{});
    strike.ball = id;
    strike.speed = 1.0;
    strike.side = strike.height = strike.elevationDeg = 0.0;
    probe.shot = strike;
    SimulationOptions options;
    options.until = 0.0;
    const SimulationResult result = simulate(probe, options);
    const int index = result.ballIndex(id);
    return index >= 0 ? result.stateAt(index, 0.0).velocity.norm() : 0.0;
}

}  // namespace

std::optional<StrikeGuess> guessStrike(const Recording& recording, const Setup& setup, const std::string& id)
{
    const RecordedBall* ball = recording.ball(id);
    if (!ball || !moved(*ball)) return std::nullopt;
    const std::vector<RecordedSample>& s = ball->samples;
    const Vec2 start = s.front().position;
    // The first sample away from the start (the ball's first tracked motion) and the straight stretch
    // after it: samples whose direction from the start stays within 10 degrees of the first one's.
    std::size_t first = 1;
    while (first < s.size() && (s[first].position - start).norm() < 0.01) ++first;
    if (first >= s.size()) return std::nullopt;
    const Vec2 firstDirection = (s[first].position - start).normalized();
    std::size_t last = first;
    for (std::size_t k = first + 1; k < s.size(); ++k) {
        const Vec2 d = s[k].position - start;
        if (d.norm() > kAimDistance) break;
        if (d.normalized().dot(firstDirection) < std::cos(10.0 * std::numbers::pi / 180.0)) break;
        last = k;
    }
    StrikeGuess guess;
    const Vec2 aim = s[last].position - start;
    guess.headingDeg = std::atan2(aim.y(), aim.x()) * 180.0 / std::numbers::pi;
    // The speed between the first moving sample and the end of the stretch (the start sample may
    // precede the strike by a frame, so its time is not used); one sample alone: from the start.
    const std::size_t from = last > first ? first : 0;
    const double distance = (s[last].position - s[from].position).norm();
    const double duration = s[last].time - s[from].time;
    const double ballSpeed = duration > 0.0 ? distance / duration : 1.0;
    const double perCue = ballSpeedPerCueSpeed(setup, id);
    guess.speed = perCue > 0.0 ? ballSpeed / perCue : 3.0;
    return guess;
}

std::optional<Setup> setupFromRecording(const Recording& recording)
{
    Setup setup;
    setup.name = recording.name;
    setup.table = recording.table;
    setup.physics = defaultPhysics(recording.table.kind);  // a carom recording gets carom cloth
    const Table table = makeTable(recording.table);
    for (const RecordedBall& b : recording.balls) {
        Ball ball;
        ball.id = b.id;
        ball.radius = b.radius.value_or(table.ballRadius);
        ball.mass = table.ballMass;
        ball.state.position = b.samples.front().position;
        setup.balls.push_back(std::move(ball));
    }
    // Tracking noise can leave a ball a millimetre into a cushion or a neighbour: each ball goes to
    // the legal spot nearest its first sample, among the balls already placed.
    std::vector<Ball> placed;
    for (Ball& ball : setup.balls) {
        const std::optional<Vec2> spot = nearestLegalSpot(table, placed, ball.radius, ball.state.position);
        if (!spot) return std::nullopt;
        ball.state.position = *spot;
        placed.push_back(ball);
    }
    setup.simulation.maxTime = std::max(setup.simulation.maxTime, recording.duration() + 1.0);
    if (const std::optional<std::size_t> struck = firstBallToMove(recording)) {
        CueStrike shot;
        shot.ball = recording.balls[*struck].id;
        setup.shot = shot;
        if (const std::optional<StrikeGuess> guess = guessStrike(recording, setup, shot.ball)) {
            setup.shot->headingDeg = guess->headingDeg;
            setup.shot->speed = guess->speed;
        }
    }
    if (firstSetupProblem(setup)) return std::nullopt;
    return setup;
}

}  // namespace cuelab
