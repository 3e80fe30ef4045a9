#include "Recording.h"

#include <cmath>
#include <set>

namespace cuelab {

const RecordedBall* Recording::ball(const std::string& id) const
{
    for (const RecordedBall& b : balls)
        if (b.id == id) return &b;
    return nullptr;
}

double Recording::duration() const
{
    double end = 0.0;
    for (const RecordedBall& b : balls)
        if (!b.samples.empty()) end = std::max(end, b.samples.back().time);
    return end;
}

namespace {

std::string ballPath(std::size_t index) { return "balls[" + std::to_string(index) + "]"; }

std::string metres(double x)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", x);
    return text;
}

}  // namespace

std::optional<RecordingProblem> recordingProblem(const Recording& recording)
{
    if (recording.balls.empty()) return RecordingProblem{"balls", "the recording has no balls"};
    const Table table = makeTable(recording.table);
    std::set<std::string> ids;
    for (std::size_t i = 0; i < recording.balls.size(); ++i) {
        const RecordedBall& b = recording.balls[i];
        const std::string path = ballPath(i);
        if (b.id.empty()) return RecordingProblem{path + ".id", "the id is empty"};
        if (!ids.insert(b.id).second) return RecordingProblem{path + ".id", "ball \"" + b.id + "\" is listed twice"};
        if (b.radius && !(*b.radius > 0.0 && std::isfinite(*b.radius)))
            return RecordingProblem{path + ".radius", "the radius must be a positive number of metres"};
        if (b.samples.size() < 2)
            return RecordingProblem{path + ".samples", "ball \"" + b.id + "\" has " + std::to_string(b.samples.size()) +
                                                           " sample(s); at least two are needed"};
        for (std::size_t k = 0; k < b.samples.size(); ++k) {
            const RecordedSample& s = b.samples[k];
            const std::string at = path + ".samples[" + std::to_string(k) + "]";
            if (!std::isfinite(s.time) || !std::isfinite(s.position.x()) || !std::isfinite(s.position.y()))
                return RecordingProblem{at, "a number is not finite"};
            if (k > 0 && !(s.time > b.samples[k - 1].time))
                return RecordingProblem{at, "time " + metres(s.time) + " s is not after the sample before it (" +
                                                metres(b.samples[k - 1].time) + " s)"};
            const double beyond = std::max({-s.position.x(), s.position.x() - table.length, -s.position.y(),
                                            s.position.y() - table.width});
            if (beyond > kOffTableTolerance)
                return RecordingProblem{at, "ball \"" + b.id + "\" is off the table by " + metres(beyond * 1000.0) +
                                                " mm (the playing surface is " + metres(table.length) + " m x " +
                                                metres(table.width) + " m)"};
        }
    }
    return std::nullopt;
}

std::optional<double> firstMoveTime(const RecordedBall& ball)
{
    if (ball.samples.empty()) return std::nullopt;
    const Vec2 start = ball.samples.front().position;
    for (const RecordedSample& s : ball.samples)
        if ((s.position - start).norm() > kMovedDistance) return s.time;
    return std::nullopt;
}

bool moved(const RecordedBall& ball) { return firstMoveTime(ball).has_value(); }

std::optional<std::size_t> firstBallToMove(const Recording& recording)
{
    std::optional<std::size_t> first;
    double earliest = 0.0;
    for (std::size_t i = 0; i < recording.balls.size(); ++i) {
        const std::optional<double> t = firstMoveTime(recording.balls[i]);
        if (t && (!first || *t < earliest)) {
            first = i;
            earliest = *t;
        }
    }
    return first;
}

}  // namespace cuelab
