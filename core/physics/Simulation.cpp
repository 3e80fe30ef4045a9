// The event loop (issue 3): next event -> evolve its agents to its time -> resolve it -> re-predict
// only the balls it involved. Balls evolve lazily: each keeps the start time and state of its
// current motion segment, and everything it will do is predicted from that segment's closed form.

#include "Simulation.h"

#include "BallBallCollision.h"
#include "BroadPhase.h"
#include "CueImpact.h"
#include "CushionCollision.h"
#include "Detection.h"
#include "EventQueue.h"
#include "Motion.h"
#include "SeparationFloor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace cuelab {

namespace {

// m: how far ahead a moving ball's pair predictions look. Predicting pairs only over the next
// kLookahead of travel keeps the box of each ball small, so the grid and the boxes cull almost
// every pair even on a large table with many balls; the price is one internal refresh per
// kLookahead travelled.
constexpr double kLookahead = 1.0;

// m: side of the broad-phase grid's cells, about half the longest window of a moving ball.
constexpr double kCellSize = 0.5;

class Simulator {
public:
    Simulator(SimulationResult& result, double limit, long long maxEvents)
        : r_(result), table_(result.table), p_(result.physics), n_(static_cast<int>(result.balls.size())),
          limit_(limit), maxEvents_(maxEvents)
    {
        const std::size_t n = static_cast<std::size_t>(n_);
        start_.assign(n, 0.0);
        state_.resize(n);
        path_.resize(n);
        end_.assign(n, kNever);
        box_.resize(n);
        own_.resize(n);
        horizon_.assign(n, kNever);
        window_.resize(n);
        pair_.assign(n * n, kNever);
        partners_.assign(n, {});
        rowMin_.assign(n, kNever);
        rowPartner_.assign(n, -1);
        queue_.reset(n_);
        double margin = 0.0;  // pockets and jaws lie beyond the cushion noses
        for (const Pocket& k : table_.pockets) margin = std::max(margin, k.radius);
        margin += 0.1;
        grid_.reset(Vec2(-margin, -margin), Vec2(table_.length + margin, table_.width + margin), kCellSize, n_);
        r_.timelines.assign(n, {});
        // Room for a typical run, so that the event loop rarely allocates.
        for (std::size_t i = 0; i < n; ++i) {
            r_.timelines[i].reserve(16);
            partners_[i].reserve(8);
        }
    }

    void run(const std::optional<CueStrike>& shot);

private:
    double radius(int i) const { return r_.balls[static_cast<std::size_t>(i)].radius; }
    double mass(int i) const { return r_.balls[static_cast<std::size_t>(i)].mass; }
    std::size_t at(int i) const { return static_cast<std::size_t>(i); }
    double& pair(int i, int j) { return pair_[at(i) * at(n_) + at(j)]; }

    BallState stateNow(int i, double t) const { return evolve(state_[at(i)], radius(i), p_, t - start_[at(i)]); }
    Path pathNow(int i, double t) const;
    void beginSegment(int i, double t, const BallState& s);
    void predictOwn(int i, double now);
    void predictPairs(int i, double now);
    void rescanRow(int j);
    void updateQueue(int i);
    double pairTime(int i, int j, double now) const;
    void process(const Candidate& c);
    bool atRest(int i) const;

    SimulationResult& r_;
    const Table& table_;
    const PhysicsParams& p_;
    int n_;
    double limit_;
    long long maxEvents_;

    // Flat per-ball arrays: the current motion segment and its predictions.
    std::vector<double> start_;      // s, when the segment began
    std::vector<BallState> state_;   // the state at start_
    std::vector<Path> path_;         // position over the segment, from start_
    std::vector<double> end_;        // s, absolute time of the transition that ends the segment
    std::vector<Box> box_;           // where the centre can be during the segment
    std::vector<Candidate> own_;     // next transition, pocket, cushion or jaw event, or refresh
    std::vector<double> horizon_;    // s, absolute end of the ball's prediction window
    std::vector<Box> window_;        // where the centre can be from the last prediction to horizon_
    std::vector<double> pair_;       // n x n, next contact time of each pair (symmetric), kNever if none
    std::vector<std::vector<int>> partners_;  // per ball, the balls it may have a finite pair_ with
    std::vector<double> rowMin_;     // per ball, the earliest of its row of pair_
    std::vector<int> rowPartner_;    // and the partner (the smallest index among ties)
    BoxGrid grid_;
    EventQueue queue_;
};

Path Simulator::pathNow(int i, double t) const
{
    // The segment's polynomial shifted to the origin t: p(tau0 + s) expanded in s.
    return path_[at(i)].shifted(t - start_[at(i)]);
}

bool Simulator::atRest(int i) const
{
    const MotionState m = state_[at(i)].motion;
    return m == MotionState::Stationary || m == MotionState::Pocketed;
}

void Simulator::beginSegment(int i, double t, const BallState& s)
{
    BallState st = s;
    if (st.motion != MotionState::Pocketed) st.motion = classify(st, radius(i));
    start_[at(i)] = t;
    state_[at(i)] = st;
    path_[at(i)] = pathOf(st, radius(i), p_);
    const Transition tr = nextTransition(st, radius(i), p_);
    end_[at(i)] = tr.after == kNever ? kNever : t + tr.after;
    box_[at(i)] = boxOf(path_[at(i)], tr.after);
    r_.timelines[at(i)].push_back(MotionSegment{t, st});
}

void Simulator::predictOwn(int i, double now)
{
    Candidate best;
    best.ball = i;
    const BallState& s = state_[at(i)];
    const Path p = pathNow(i, now);
    window_[at(i)] = boxOf(p, 0.0);
    horizon_[at(i)] = end_[at(i)];
    if (s.motion == MotionState::Pocketed) {
        own_[at(i)] = best;
        grid_.remove(i);
        return;
    }
    if (end_[at(i)] != kNever) best = Candidate{end_[at(i)], 0, i, Agent::Transition, 0};
    const bool moving = s.motion == MotionState::Sliding || s.motion == MotionState::Rolling;
    if (moving) {
        const double horizon = end_[at(i)] - now;
        const double R = radius(i);
        const Box& box = box_[at(i)];
        auto consider = [&](double ds, int category, Agent agent, int index) {
            if (ds == kNever) return;
            const Candidate c{now + ds, category, i, agent, index};
            if (earlier(c, best)) best = c;
        };
        for (std::size_t k = 0; k < table_.pockets.size(); ++k)
            if (boxNearCircle(box, table_.pockets[k].radius, table_.pockets[k].centre))
                consider(pocketTime(p, table_.pockets[k], horizon), 0, Agent::Pocket, static_cast<int>(k));
        for (std::size_t k = 0; k < table_.cushions.size(); ++k)
            if (boxNearSegment(box, R, table_.cushions[k]))
                consider(cushionTime(p, R, table_.cushions[k], horizon), 1, Agent::Cushion, static_cast<int>(k));
        for (std::size_t k = 0; k < table_.jaws.size(); ++k)
            if (boxNearCircle(box, R + table_.jaws[k].radius, table_.jaws[k].centre))
                consider(jawTime(p, R, table_.jaws[k], horizon), 1, Agent::Jaw, static_cast<int>(k));
        // The pair window ends at the ball's own next event (it is re-predicted there anyway) or after
        // kLookahead of travel, whichever comes first; |r(t) - r(now)| <= |v(now)| (t - now) while
        // the ball decelerates.
        const double lookahead = now + kLookahead / p.c1.norm();
        // (At an absurd speed the window would round to nothing: then it ends at the own event.)
        if (lookahead > now && lookahead < best.time) best = Candidate{lookahead, 0, i, Agent::Refresh, 0};
        horizon_[at(i)] = best.time;
        window_[at(i)] = boxOf(p, best.time - now);
    }
    own_[at(i)] = best;
    Box grown = window_[at(i)];
    grown.lo.array() -= radius(i);
    grown.hi.array() += radius(i);
    grid_.place(i, grown);
}

double Simulator::pairTime(int i, int j, double now) const
{
    const BallState& a = state_[at(i)];
    const BallState& b = state_[at(j)];
    if (a.motion == MotionState::Pocketed || b.motion == MotionState::Pocketed) return kNever;
    const bool aMoves = a.motion == MotionState::Sliding || a.motion == MotionState::Rolling;
    const bool bMoves = b.motion == MotionState::Sliding || b.motion == MotionState::Rolling;
    if (!aMoves && !bMoves) return kNever;
    if (!boxesMeet(window_[at(i)], radius(i), window_[at(j)], radius(j))) return kNever;
    const double horizon = std::min(horizon_[at(i)], horizon_[at(j)]) - now;
    if (horizon < 0.0) return kNever;  // j is refreshed at this very instant, and predicts the pair then
    const double s = ballBallTime(pathNow(i, now), radius(i), pathNow(j, now), radius(j), horizon);
    return s == kNever ? kNever : now + s;
}

void Simulator::updateQueue(int i)
{
    Candidate best = own_[at(i)];
    const int j = rowPartner_[at(i)];
    if (j >= 0 && rowMin_[at(i)] != kNever) {
        const Candidate c{rowMin_[at(i)], 1, std::min(i, j), Agent::Ball, std::max(i, j)};
        if (earlier(c, best)) best = c;
    }
    queue_.set(i, best);
}

void Simulator::rescanRow(int j)
{
    // Recomputes j's earliest partner from its partner list, dropping the entries that are stale.
    std::vector<int>& list = partners_[at(j)];
    double m = kNever;
    int q = -1;
    std::size_t kept = 0;
    for (std::size_t k = 0; k < list.size(); ++k) {
        const int other = list[k];
        const double t = pair(j, other);
        if (t == kNever) continue;
        bool duplicate = false;
        for (std::size_t d = 0; d < kept && !duplicate; ++d) duplicate = list[d] == other;
        if (duplicate) continue;
        list[kept++] = other;
        if (t < m || (t == m && other < q)) {
            m = t;
            q = other;
        }
    }
    list.resize(kept);
    rowMin_[at(j)] = m;
    rowPartner_[at(j)] = q;
    updateQueue(j);
}

void Simulator::predictPairs(int i, double now)
{
    // Forget i's old pair predictions; the partners whose earliest pair was with i look again.
    std::vector<int>& mine = partners_[at(i)];
    for (int j : mine) {
        if (pair(i, j) == kNever) continue;
        pair(i, j) = pair(j, i) = kNever;
        if (rowPartner_[at(j)] == i) rescanRow(j);
    }
    mine.clear();

    double best = kNever;
    int partner = -1;
    if (state_[at(i)].motion != MotionState::Pocketed) {
        Box grown = window_[at(i)];
        grown.lo.array() -= radius(i);
        grown.hi.array() += radius(i);
        grid_.forEachNear(i, grown, [&](int j) {
            const double t = pairTime(i, j, now);
            if (t == kNever) return;
            pair(i, j) = pair(j, i) = t;
            mine.push_back(j);
            partners_[at(j)].push_back(i);
            if (t < best || (t == best && j < partner)) {
                best = t;
                partner = j;
            }
            if (t < rowMin_[at(j)] || (t == rowMin_[at(j)] && i < rowPartner_[at(j)])) {
                rowMin_[at(j)] = t;
                rowPartner_[at(j)] = i;
                updateQueue(j);
            }
        });
    }
    rowMin_[at(i)] = best;
    rowPartner_[at(i)] = partner;
    updateQueue(i);
}

void Simulator::process(const Candidate& c)
{
    const double t = c.time;
    const int i = c.ball;
    if (c.agent == Agent::Refresh) {
        predictOwn(i, t);
        predictPairs(i, t);
        return;
    }
    Event e;
    e.time = t;
    e.balls[0] = i;
    e.before[0] = stateNow(i, t);
    switch (c.agent) {
    case Agent::Refresh:  // handled above
    case Agent::Transition: {
        e.after[0] = applyTransition(state_[at(i)], radius(i), p_);
        e.kind = nextTransition(state_[at(i)], radius(i), p_).kind;
        break;
    }
    case Agent::Pocket: {
        const Pocket& pocket = table_.pockets[at(c.index)];
        e.kind = EventKind::BallPocket;
        e.pocket = c.index;
        e.after[0] = BallState{};
        e.after[0].position = pocket.centre;
        e.after[0].motion = MotionState::Pocketed;
        e.after[0].pocket = c.index;
        e.contactPoint = e.before[0].position;
        break;
    }
    case Agent::Cushion:
    case Agent::Jaw: {
        Vec2 normal;  // from the cushion towards the ball
        if (c.agent == Agent::Cushion) {
            const CushionSegment& seg = table_.cushions[at(c.index)];
            normal = seg.normal;
            e.kind = EventKind::BallCushion;
            e.cushion = c.index;
        } else {
            const JawTip& jaw = table_.jaws[at(c.index)];
            normal = (e.before[0].position - jaw.centre).normalized();
            e.kind = EventKind::BallJaw;
            e.jaw = c.index;
        }
        CushionResult res = resolveCushion(e.before[0], normal, radius(i), mass(i), table_.cushionHeight, p_);
        enforceSeparation(res, normal, mass(i));
        res.after.motion = classify(res.after, radius(i));
        e.after[0] = res.after;
        e.contactPoint = e.before[0].position - radius(i) * normal;
        e.normal = -normal;
        e.approachSpeed = res.approachSpeed;
        e.impulse = res.impulse;
        break;
    }
    case Agent::Ball: {
        const int j = c.index;
        e.kind = EventKind::BallBall;
        e.balls[1] = j;
        e.before[1] = stateNow(j, t);
        BallBallResult res = resolveBallBall({e.before[0], radius(i), mass(i)}, {e.before[1], radius(j), mass(j)}, p_);
        enforceSeparation(res, mass(i), mass(j));
        res.a.motion = classify(res.a, radius(i));
        res.b.motion = classify(res.b, radius(j));
        e.after[0] = res.a;
        e.after[1] = res.b;
        e.contactPoint = res.contactPoint;
        e.normal = res.normal;
        e.approachSpeed = res.approachSpeed;
        e.impulse = res.impulse;
        break;
    }
    }
    r_.events.push_back(e);
    for (int k = 0; k < 2; ++k)
        if (e.balls[static_cast<std::size_t>(k)] >= 0)
            beginSegment(e.balls[static_cast<std::size_t>(k)], t, e.after[static_cast<std::size_t>(k)]);
    for (int k = 0; k < 2; ++k)
        if (e.balls[static_cast<std::size_t>(k)] >= 0) predictOwn(e.balls[static_cast<std::size_t>(k)], t);
    for (int k = 0; k < 2; ++k)
        if (e.balls[static_cast<std::size_t>(k)] >= 0) predictPairs(e.balls[static_cast<std::size_t>(k)], t);
}

void Simulator::run(const std::optional<CueStrike>& shot)
{
    for (int i = 0; i < n_; ++i) beginSegment(i, 0.0, r_.balls[at(i)].state);

    if (shot) {
        const int i = r_.ballIndex(shot->ball);
        if (i >= 0 && state_[at(i)].motion != MotionState::Pocketed) {
            const CueImpactResult strike = resolveCueStrike(state_[at(i)], radius(i), mass(i), *shot);
            Event e;
            e.kind = EventKind::CueStrike;
            e.time = 0.0;
            e.balls[0] = i;
            e.before[0] = state_[at(i)];
            e.after[0] = strike.after;
            e.contactPoint = strike.contactPoint;
            e.normal = strike.heading;
            e.approachSpeed = shot->speed;
            e.impulse = strike.impulse;
            r_.events.push_back(e);
            beginSegment(i, 0.0, strike.after);
        }
    }
    for (int i = 0; i < n_; ++i) predictOwn(i, 0.0);
    for (int i = 0; i < n_; ++i) predictPairs(i, 0.0);

    double lastEvent = 0.0;
    for (;;) {
        const Candidate c = queue_.top();
        if (c.time == kNever || c.time > limit_) break;
        if (static_cast<long long>(r_.events.size()) >= maxEvents_) {
            r_.status = SimulationStatus::EventLimit;
            r_.endTime = lastEvent;
            std::ostringstream msg;
            msg << "the simulation stopped after " << maxEvents_ << " events at t = " << lastEvent
                << " s with balls still moving (event limit reached)";
            r_.error = msg.str();
            return;
        }
        process(c);
        if (c.agent != Agent::Refresh) lastEvent = c.time;
    }
    bool rest = true;
    for (int i = 0; i < n_; ++i) rest = rest && atRest(i);
    if (rest) {
        r_.status = SimulationStatus::AllAtRest;
        r_.endTime = r_.events.empty() ? 0.0 : lastEvent;
    } else {
        r_.status = SimulationStatus::ReachedUntil;
        r_.endTime = limit_;
    }
}

}  // namespace

BallState SimulationResult::stateAt(int index, double t) const
{
    // A time that is not finite has no state (NaN fails every comparison of the search below, and
    // evolving by an infinite span gives NaN): refused like a bad index.
    if (!std::isfinite(t)) throw std::domain_error("SimulationResult::stateAt: the time is not a finite number");
    const std::vector<MotionSegment>& timeline = timelines.at(static_cast<std::size_t>(index));
    const double R = balls.at(static_cast<std::size_t>(index)).radius;
    // The last segment starting at or before t: at an event time, the state just after it.
    auto it = std::upper_bound(timeline.begin(), timeline.end(), t,
                               [](double time, const MotionSegment& s) { return time < s.start; });
    if (it != timeline.begin()) --it;
    BallState s = it->state;
    double start = it->start;
    // Past the run's end (a time limit) the ball carries on through its transitions, collision-free.
    for (;;) {
        const Transition tr = nextTransition(s, R, physics);
        if (tr.after == kNever || start + tr.after > t) break;
        s = applyTransition(s, R, physics);
        start += tr.after;
    }
    return evolve(s, R, physics, t - start);
}

std::vector<BallState> SimulationResult::statesAt(double t) const
{
    std::vector<BallState> out;
    out.reserve(balls.size());
    for (std::size_t i = 0; i < balls.size(); ++i) out.push_back(stateAt(static_cast<int>(i), t));
    return out;
}

int SimulationResult::ballIndex(const std::string& id) const
{
    for (std::size_t i = 0; i < balls.size(); ++i)
        if (balls[i].id == id) return static_cast<int>(i);
    return -1;
}

SimulationResult simulate(const Setup& setup, const SimulationOptions& options)
{
    SimulationResult r;
    r.table = makeTable(setup.table);
    r.physics = setup.physics;
    r.balls = setup.balls;
    const double limit = options.until >= 0.0 ? std::min(options.until, setup.simulation.maxTime)
                                              : setup.simulation.maxTime;
    r.events.reserve(64 + 16 * setup.balls.size());
    Simulator sim(r, limit, options.maxEvents);
    sim.run(setup.shot);
    return r;
}

}  // namespace cuelab
