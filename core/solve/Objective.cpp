#include "Objective.h"

#include "Map.h"
#include "Parallel.h"
#include "ShotOdds.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cuelab::solve {

using analysis::GoalTerm;

namespace {

constexpr double kMissPenalty = 0.05;        // m, a miss is at least this much worse than any pot
constexpr double kOtherTermPenalty = 0.3;    // m
constexpr double kScratchPenalty = 0.5;      // m
constexpr double kOffTablePenalty = 2.0;     // m, a ball that should stop in a zone but is gone
constexpr int kSamplesPerJob = 8;
constexpr double kMissWorth = 0.5;           // the most a missing draw is worth
constexpr double kClosenessScale = 0.1;      // m: a miss by this much is worth half of kMissWorth
constexpr int kPointsPerSegment = 12;        // a sliding segment curves: its path is read at this many points

double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b)
{
    const Vec2 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (a + t * ab - p).norm();
}

// The nearest the centre of ball `ball` comes to `target` over the whole shot (a polyline through
// each motion segment).
double nearestApproach(const SimulationResult& r, int ball, const Vec2& target)
{
    const auto& timeline = r.timelines[static_cast<std::size_t>(ball)];
    const double radius = r.balls[static_cast<std::size_t>(ball)].radius;
    double best = 1e9;
    for (std::size_t k = 0; k < timeline.size(); ++k) {
        const MotionSegment& seg = timeline[k];
        if (seg.state.motion == MotionState::Pocketed || seg.state.motion == MotionState::OffTable) break;
        const double end = k + 1 < timeline.size() ? timeline[k + 1].start : r.endTime;
        const double span = std::max(0.0, end - seg.start);
        Vec2 previous = seg.state.position;
        best = std::min(best, (previous - target).norm());
        if (span <= 0.0 || seg.state.motion == MotionState::Stationary) continue;
        for (int i = 1; i <= kPointsPerSegment; ++i) {
            const double dt = span * static_cast<double>(i) / kPointsPerSegment;
            const Vec2 p = segmentState(seg, radius, r.physics, dt).position;
            best = std::min(best, pointSegmentDistance(target, previous, p));
            previous = p;
        }
    }
    return best;
}

}  // namespace

Evaluator::Evaluator(const Setup& setup, const analysis::Goal& goal, const SolveRequest& request, std::stop_token stop)
    : setup_(setup), simulation_(request.simulation), threads_(resolveThreads(request.threads)), stop_(std::move(stop))
{
    if (stop_.stop_possible()) simulation_.cancel = stop_;
    std::string error;
    auto resolved = analysis::ResolvedGoal::resolve(goal, setup_, &error);
    if (!resolved) throw std::invalid_argument(error);
    resolved_ = std::move(*resolved);
    const Table table = makeTable(setup_.table);
    for (const GoalTerm& t : goal.terms) {
        TermCheck check;
        check.term = t;
        // (A term that resolves within the goal resolves alone; the whole goal stands in otherwise.)
        auto alone = analysis::ResolvedGoal::resolve(analysis::Goal{{t}}, setup_, nullptr);
        check.alone = alone ? std::move(*alone) : resolved_;
        for (std::size_t i = 0; i < setup_.balls.size(); ++i)
            if (setup_.balls[i].id == t.ball) check.ball = static_cast<int>(i);
        if (t.kind == GoalTerm::Kind::Pocketed)
            for (std::size_t p = 0; p < table.pockets.size(); ++p)
                if (t.pocket.empty() || table.pockets[p].id == t.pocket) check.pockets.push_back(static_cast<int>(p));
        terms_.push_back(std::move(check));
    }
}

Strike Evaluator::baseStrike() const
{
    const CueStrike& s = *setup_.shot;
    return {s.headingDeg, s.speed, s.side, s.height, s.elevationDeg};
}

Setup Evaluator::setupWith(const Strike& strike) const
{
    Setup s = setup_;
    s.shot->headingDeg = strike[0];
    s.shot->speed = strike[1];
    s.shot->side = strike[2];
    s.shot->height = strike[3];
    s.shot->elevationDeg = strike[4];
    return s;
}

double Evaluator::closeness(const SimulationResult& r, const ShotOutcome& o) const
{
    double sum = 0.0;
    for (const TermCheck& c : terms_) {
        const bool holds = c.alone.met(r, o);
        if (c.term.kind == GoalTerm::Kind::Pocketed && !c.term.negated && c.ball >= 0) {
            const PocketedBall* dropped = nullptr;
            for (const PocketedBall& p : o.pocketed)
                if (p.ball == c.ball && std::find(c.pockets.begin(), c.pockets.end(), p.pocket) != c.pockets.end())
                    dropped = &p;
            if (dropped) {
                // The miss distance of its line of entry from the pocket's centre.
                for (const Event& e : r.events) {
                    if (e.kind != EventKind::BallPocket || e.balls[0] != c.ball) continue;
                    const Vec2 position = e.before[0].position;
                    const Vec2 velocity = e.before[0].velocity;
                    const Vec2 toCentre = r.table.pockets[static_cast<std::size_t>(e.pocket)].centre - position;
                    const double speed = velocity.norm();
                    sum += speed > 0.0 ? std::abs(velocity.x() * toCentre.y() - velocity.y() * toCentre.x()) / speed
                                       : toCentre.norm();
                    break;
                }
            } else {
                double nearest = 1e9;
                for (int p : c.pockets) {
                    const Pocket& pocket = r.table.pockets[static_cast<std::size_t>(p)];
                    nearest = std::min(nearest, std::max(pocket.radius, nearestApproach(r, c.ball, pocket.centre)));
                }
                sum += kMissPenalty + (c.pockets.empty() ? 1.0 : nearest);
            }
        } else if (c.term.kind == GoalTerm::Kind::EndsInRegion && !c.term.negated && c.ball >= 0) {
            const BallState& end = o.finalStates[static_cast<std::size_t>(c.ball)];
            if (end.motion == MotionState::Pocketed || end.motion == MotionState::OffTable) {
                sum += kOffTablePenalty;
            } else {
                const analysis::Region& g = c.term.region;
                const Vec2 p = end.position;
                const double x0 = std::min(g.x0, g.x1), x1 = std::max(g.x0, g.x1);
                const double y0 = std::min(g.y0, g.y1), y1 = std::max(g.y0, g.y1);
                const double dx = std::max({x0 - p.x(), 0.0, p.x() - x1});
                const double dy = std::max({y0 - p.y(), 0.0, p.y() - y1});
                const Vec2 centre(0.5 * (x0 + x1), 0.5 * (y0 + y1));
                sum += std::hypot(dx, dy) + 0.25 * (p - centre).norm();
            }
        } else if (!holds) {
            sum += c.term.kind == GoalTerm::Kind::StruckBallUp && !c.term.negated ? kScratchPenalty : kOtherTermPenalty;
        }
    }
    return sum;
}

Nominal Evaluator::nominal(const Strike& strike) const
{
    Nominal n;
    ++simulations_;
    const Setup s = setupWith(strike);
    try {
        n.result = simulate(s, simulation_);
    } catch (const std::exception&) {
        return n;
    }
    if (!n.result.finished()) return n;
    n.simulated = true;
    n.outcome = shotOutcome(n.result);
    n.met = resolved_.met(n.result, n.outcome);
    n.closeness = closeness(n.result, n.outcome);
    return n;
}

double Evaluator::drawValue(const Strike& strike, bool* met) const
{
    *met = false;
    // As `odds` judges a sample (ShotOdds.cpp): a tip beyond the miscue limit is a miscue and a
    // speed below 0 is refused, both failures.
    if (std::hypot(strike[2], strike[3]) > analysis::kMiscueLimit * (1.0 + 1e-12) || strike[1] < 0.0)
        return 0.0;
    const Nominal n = nominal(strike);
    if (!n.simulated) return 0.0;
    *met = n.met;
    return n.met ? 1.0 : kMissWorth / (1.0 + n.closeness / kClosenessScale);
}

std::vector<Score> Evaluator::score(const std::vector<Strike>& candidates, const analysis::NoiseModel& noise,
                                    std::uint64_t crnSeed, int samples)
{
    // Jobs: per candidate, its noise-free shot and then its samples in chunks.
    const long long chunks = (samples + kSamplesPerJob - 1) / kSamplesPerJob;
    const long long perCandidate = 1 + chunks;
    const long long jobs = static_cast<long long>(candidates.size()) * perCandidate;
    std::vector<int> successes(static_cast<std::size_t>(jobs), 0);
    std::vector<double> values(static_cast<std::size_t>(jobs), 0.0);
    std::vector<double> closeness(candidates.size(), 1e9);
    std::vector<char> met(candidates.size(), 0);
    parallelFor(
        jobs, threads_,
        [&](long long job) {
            const auto c = static_cast<std::size_t>(job / perCandidate);
            const long long part = job % perCandidate;
            if (part == 0) {
                const Nominal n = nominal(candidates[c]);
                closeness[c] = n.closeness;
                met[c] = n.met ? 1 : 0;
                return;
            }
            const long long first = (part - 1) * kSamplesPerJob;
            const long long end = std::min<long long>(samples, first + kSamplesPerJob);
            int count = 0;
            double sum = 0.0;
            for (long long i = first; i < end; ++i) {
                bool drawMet = false;
                sum += drawValue(analysis::noisyStrike(candidates[c], noise, crnSeed, i), &drawMet);
                if (drawMet) ++count;
            }
            values[static_cast<std::size_t>(job)] = sum;
            successes[static_cast<std::size_t>(job)] = count;
        },
        stop_);
    std::vector<Score> scores(candidates.size());
    for (std::size_t c = 0; c < candidates.size(); ++c) {
        Score& s = scores[c];
        s.samples = samples;
        double sum = 0.0;
        for (long long part = 1; part < perCandidate; ++part) {
            const std::size_t j = c * static_cast<std::size_t>(perCandidate) + static_cast<std::size_t>(part);
            s.successes += successes[j];
            sum += values[j];
        }
        s.value = samples > 0 ? sum / samples : 0.0;
        s.closeness = closeness[c];
        s.nominalMet = met[c] != 0;
    }
    return scores;
}

}  // namespace cuelab::solve
