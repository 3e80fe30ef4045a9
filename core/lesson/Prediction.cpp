#include "Prediction.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cuelab::lesson {

namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

bool involves(const Event& e, int ball) { return e.balls[0] == ball || e.balls[1] == ball; }

const BallState& stateOf(const Event& e, int ball, bool after)
{
    const int k = e.balls[0] == ball ? 0 : 1;
    return after ? e.after[k] : e.before[k];
}

double headingOf(const Vec2& v) { return std::atan2(v.y(), v.x()) * kDegPerRad; }

}  // namespace

int firstCollisionEvent(const SimulationResult& result)
{
    const auto& events = result.events;
    for (std::size_t i = 0; i < events.size(); ++i)
        if (events[i].kind == EventKind::BallBall) return static_cast<int>(i);
    for (std::size_t i = 0; i < events.size(); ++i)
        if (isCollision(events[i].kind)) return static_cast<int>(i);
    return -1;
}

std::vector<AskedQuestion> askedQuestions(const std::vector<PredictQuestion>& questions, const SimulationResult& result,
                                          std::vector<std::string>* problems)
{
    std::vector<AskedQuestion> asked;
    const int eventCount = static_cast<int>(result.events.size());
    for (std::size_t q = 0; q < questions.size(); ++q) {
        const PredictQuestion& question = questions[q];
        // Problems are numbered for people, from 1, as the Predict dock lists the questions.
        const std::string name = "question " + std::to_string(q + 1) + ": ";
        const auto problem = [&](const std::string& text) {
            if (problems) problems->push_back(name + text);
        };
        AskedQuestion a;
        a.question = static_cast<int>(q);
        a.event = question.event ? *question.event : firstCollisionEvent(result);
        if (a.event < 0) {
            problem("the shot has no collision to stop before");
            continue;
        }
        if (a.event >= eventCount) {
            problem("event #" + std::to_string(a.event + 1) + " does not happen: the shot has only " +
                    std::to_string(eventCount) + " events");
            continue;
        }
        const Event& e = result.events[static_cast<std::size_t>(a.event)];
        a.time = e.time;
        bool known = true;
        for (const std::string& id : question.balls) {
            const int index = result.ballIndex(id);
            if (index < 0) {
                problem("no ball \"" + id + "\" in the shot");
                known = false;
                break;
            }
            if (std::find(a.balls.begin(), a.balls.end(), index) == a.balls.end()) a.balls.push_back(index);
        }
        if (!known) continue;
        if (a.balls.empty())
            for (int b : e.balls)
                if (b >= 0) a.balls.push_back(b);
        a.prompt = question.prompt;
        asked.push_back(std::move(a));
    }
    std::stable_sort(asked.begin(), asked.end(), [](const AskedQuestion& x, const AskedQuestion& y) { return x.event < y.event; });
    return asked;
}

std::optional<double> actualHeading(const SimulationResult& result, int event, int ball)
{
    const auto& events = result.events;
    if (event < 0 || event >= static_cast<int>(events.size()) || ball < 0 || ball >= static_cast<int>(result.balls.size()))
        return std::nullopt;
    const Event& at = events[static_cast<std::size_t>(event)];
    // Where the ball is as the event ends (its own state after it, else its state at that time).
    const Vec2 start = involves(at, ball) ? stateOf(at, ball, true).position : result.stateAt(ball, at.time).position;
    Vec2 end = start;
    std::optional<Vec2> velocity;
    bool settled = false;
    for (std::size_t i = static_cast<std::size_t>(event) + 1; i < events.size() && !settled; ++i) {
        const Event& e = events[i];
        if (!involves(e, ball)) continue;
        const BallState& before = stateOf(e, ball, false);
        switch (e.kind) {
        case EventKind::SlideToRoll:
        case EventKind::SlideToSpin:
        case EventKind::BallBall:
        case EventKind::BallCushion:
        case EventKind::BallJaw:
        case EventKind::BallPocket:
        case EventKind::BallOffTable:
            // Rolling begins, or the next collision: the direction the ball is going now.
            end = before.position;
            velocity = before.velocity;
            settled = true;
            break;
        case EventKind::SlideToStop:
        case EventKind::RollToStop:
        case EventKind::SpinToStop:
            // It came to rest (a spinning ball has stopped travelling already): where it moved to.
            end = before.position;
            settled = true;
            break;
        case EventKind::RollToSpin:
        case EventKind::CueStrike:
        case EventKind::BallTable:  // a bounce: the ball goes on
            break;
        }
    }
    if (!settled) {
        // No later event of its own within the run: where it is at the end.
        const BallState last = result.stateAt(ball, result.endTime);
        end = last.position;
        if (last.velocity.norm() > 0.0) velocity = last.velocity;
    }
    if ((end - start).norm() < kStillDistance) return std::nullopt;
    if (velocity && velocity->norm() > 0.0) return headingOf(*velocity);
    return headingOf(end - start);
}

double angleBetween(double headingA, double headingB)
{
    const double d = std::fmod(std::abs(headingA - headingB), 360.0);
    return d > 180.0 ? 360.0 - d : d;
}

BallReveal scoreBall(int ball, const BallPrediction& predicted, std::optional<double> actualDeg)
{
    BallReveal r;
    r.ball = ball;
    r.predicted = predicted;
    r.actualDeg = actualDeg;
    if (!predicted.answered) {
        r.verdict = Verdict::NoAnswer;
        return r;
    }
    if (!predicted.headingDeg || !actualDeg) {
        const bool right = !predicted.headingDeg && !actualDeg;
        r.verdict = right ? Verdict::Right : Verdict::Wrong;
        r.score = right ? 1.0 : 0.0;
        return r;
    }
    const double error = angleBetween(*predicted.headingDeg, *actualDeg);
    r.errorDeg = error;
    r.score = std::max(0.0, 1.0 - error / 90.0);
    r.verdict = error <= kSpotOnDeg ? Verdict::SpotOn : error <= kCloseDeg ? Verdict::Close : Verdict::Off;
    return r;
}

std::vector<BallReveal> reveal(const AskedQuestion& question, const std::vector<BallPrediction>& predictions,
                               const SimulationResult& result)
{
    std::vector<BallReveal> out;
    for (std::size_t i = 0; i < question.balls.size(); ++i) {
        const int ball = question.balls[i];
        const BallPrediction p = i < predictions.size() ? predictions[i] : BallPrediction{};
        out.push_back(scoreBall(ball, p, actualHeading(result, question.event, ball)));
    }
    return out;
}

double questionScore(const std::vector<BallReveal>& balls)
{
    if (balls.empty()) return 0.0;
    double sum = 0.0;
    for (const BallReveal& b : balls) sum += b.score;
    return sum / static_cast<double>(balls.size());
}

}  // namespace cuelab::lesson
