// The event loop (issue 3): next event -> evolve its agents to its time -> resolve it -> re-predict
// only the balls it involved. Balls evolve lazily: each keeps the start time and state of its
// current motion segment, and everything it will do is predicted from that segment's closed form.

#include "Simulation.h"

#include "BallBallCollision.h"
#include "BallContact.h"
#include "BroadPhase.h"
#include "CueImpact.h"
#include "CushionCollision.h"
#include "Detection.h"
#include "EventQueue.h"
#include "Motion.h"
#include "Contact.h"

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
        push_.assign(n, Vec2::Zero());
        heldCount_.assign(n, 0);
        regroupAt_.assign(n, kNever);
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

    BallState stateNow(int i, double t) const
    {
        return evolve(state_[at(i)], radius(i), p_, t - start_[at(i)], push_[at(i)]);
    }
    Path pathNow(int i, double t) const;
    void beginSegment(int i, double t, const BallState& s, const Vec2& push = Vec2::Zero());
    void predictOwn(int i, double now);
    void predictPairs(int i, double now);
    void rescanRow(int j);
    void updateQueue(int i);
    double pairTime(int i, int j, double now) const;
    void process(const Candidate& c);
    bool atRest(int i) const;

    // Sustained contact (Contact.h).
    bool heldPair(int i, int j) const;
    bool heldWall(int i, ContactBody body, int index) const;
    void release(std::size_t k);
    // After an event: solves the held group its balls belong to (with a contact that may begin
    // holding, `candidate`) and gives every ball of that group its new segment. Returns 0 when no
    // group is touched (the caller segments the balls freely), 1 when settled, 2 when the candidate
    // is not pressed and `forceHold` is false and it touches no held group (nothing changed), 3 when
    // such a candidate was seated with the group it touches but not held.
    int settle(double t, const std::vector<int>& eventBalls, const std::vector<BallState>& eventStates,
               const HeldContact* candidate, bool forceHold, double candidateSeparation = 0.0);
    void finishEvent(double t, const Event& e);
    double turnLimit(const std::vector<int>& members, const std::vector<HeldContact>& contacts, double t) const;

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

    std::vector<Vec2> push_;          // m/s^2, the contact force over the mass of a held ball's segment
    std::vector<HeldContact> held_;   // the contacts held now, in the order they were formed
    std::vector<int> heldCount_;      // per ball, how many of held_ involve it
    std::vector<double> regroupAt_;   // s, when a held group is solved again (kNever if none)
    std::size_t lastGroupSize_ = 0;   // how many contacts the last settle() solved
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

void Simulator::beginSegment(int i, double t, const BallState& s, const Vec2& push)
{
    BallState st = s;
    const bool free = push.isZero(0.0);
    if (free && st.motion != MotionState::Pocketed) st.motion = classify(st, radius(i));
    start_[at(i)] = t;
    state_[at(i)] = st;
    push_[at(i)] = push;
    path_[at(i)] = pathOf(st, radius(i), p_, push);
    const Transition tr = nextTransition(st, radius(i), p_, push);
    end_[at(i)] = tr.after == kNever ? kNever : t + tr.after;
    box_[at(i)] = boxOf(path_[at(i)], std::min(tr.after, regroupAt_[at(i)] - t));
    r_.timelines[at(i)].push_back(MotionSegment{t, st, push});
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
    // A held group is solved again before a frozen direction turns too far (Refresh, index 1).
    if (regroupAt_[at(i)] < best.time) best = Candidate{regroupAt_[at(i)], 0, i, Agent::Refresh, 1};
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
        const bool held = heldCount_[at(i)] > 0;
        for (std::size_t k = 0; k < table_.cushions.size(); ++k)
            if (boxNearSegment(box, R, table_.cushions[k]) && !(held && heldWall(i, ContactBody::Cushion, static_cast<int>(k))))
                consider(cushionTime(p, R, table_.cushions[k], horizon), 1, Agent::Cushion, static_cast<int>(k));
        for (std::size_t k = 0; k < table_.jaws.size(); ++k)
            if (boxNearCircle(box, R + table_.jaws[k].radius, table_.jaws[k].centre) && !(held && heldWall(i, ContactBody::Jaw, static_cast<int>(k))))
                consider(jawTime(p, R, table_.jaws[k], horizon), 1, Agent::Jaw, static_cast<int>(k));
        // The pair window ends at the ball's own next event (it is re-predicted there anyway) or after
        // kLookahead of travel, whichever comes first; |r(t) - r(now)| <= |v(now)| (t - now) while
        // the ball decelerates.
        const double speed = p.c1.norm();
        const double lookahead = speed > 0.0 ? now + kLookahead / speed : kNever;
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
    if (heldCount_[at(i)] > 0 && heldCount_[at(j)] > 0 && heldPair(i, j)) return kNever;  // held together
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

bool Simulator::heldPair(int i, int j) const
{
    for (const HeldContact& h : held_)
        if (h.body == ContactBody::Ball && ((h.a == i && h.other == j) || (h.a == j && h.other == i))) return true;
    return false;
}

bool Simulator::heldWall(int i, ContactBody body, int index) const
{
    for (const HeldContact& h : held_)
        if (h.a == i && h.body == body && h.other == index) return true;
    return false;
}

namespace {

// The kind of a pushed state's end, when its label changes (none when the push only turned it).
bool pushedTransitionKind(MotionState before, MotionState after, EventKind& kind)
{
    if (before == after) return false;
    if (before == MotionState::Sliding) {
        kind = after == MotionState::Rolling    ? EventKind::SlideToRoll
               : after == MotionState::Spinning ? EventKind::SlideToSpin
                                                : EventKind::SlideToStop;
        return after != MotionState::Sliding;
    }
    if (before == MotionState::Rolling) {
        if (after == MotionState::Spinning) kind = EventKind::RollToSpin;
        else if (after == MotionState::Stationary) kind = EventKind::RollToStop;
        else return false;
        return true;
    }
    if (before == MotionState::Spinning && after == MotionState::Stationary) {
        kind = EventKind::SpinToStop;
        return true;
    }
    return false;
}

// The first s > 0 at which c0 + c1 s + c2 s^2 = target (kNever if none).
double firstCrossing(double c0, double c1, double c2, double target)
{
    const double a = c2, b = c1, c = c0 - target;
    double best = kNever;
    auto take = [&](double s) {
        if (s > 0.0 && s < best) best = s;
    };
    if (a == 0.0) {
        if (b != 0.0) take(-c / b);
        return best;
    }
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return best;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    if (q != 0.0) take(c / q);
    take(q / a);
    return best;
}

}  // namespace

double Simulator::turnLimit(const std::vector<int>& members, const std::vector<HeldContact>& contacts, double t) const
{
    (void)t;
    double limit = kMaxHeldSegment;
    const double g = p_.gravity;
    for (int m : members) {
        const BallState& s = state_[at(m)];
        const Vec2& q = push_[at(m)];
        if (q.isZero(0.0)) continue;
        Vec2 x0 = Vec2::Zero(), rate = Vec2::Zero();  // the frozen vector and how fast it changes
        if (s.motion == MotionState::Sliding) {
            x0 = slipVelocity(s, radius(m));
            if (x0.norm() > 0.0) rate = q - (3.5 * p_.muSlide * g) * x0.normalized();
        } else if (s.motion == MotionState::Rolling && s.velocity.norm() > kRollOffSpeed) {  // (slower: from rest)
            x0 = s.velocity;
            rate = (5.0 / 7.0) * q - (p_.muRoll * g) * x0.normalized();
        }
        const double n0 = x0.norm();
        // A slip or roll that has as good as ended ends now, at its own transition.
        if (n0 <= 1e-9 * (s.velocity.norm() + radius(m) * s.spin.head<2>().norm())) continue;
        const Vec2 e = x0 / n0;
        const double along = rate.dot(e);
        const double across = (rate - along * e).norm();
        const double den = across - kMaxTurn * along;
        if (across > 1e-12 * rate.norm() && den > 0.0) limit = std::min(limit, kMaxTurn * n0 / den);
    }
    for (const HeldContact& h : contacts) {
        const Path pa = path_[at(h.a)];
        if (h.body == ContactBody::Cushion) {
            const CushionSegment& seg = table_.cushions[at(h.other)];
            const Vec2 d = seg.b - seg.a;
            const double L = d.norm();
            const Vec2 tHat = d / L;
            const double f0 = (pa.c0 - seg.a).dot(tHat), f1 = pa.c1.dot(tHat), f2 = pa.c2.dot(tHat);
            limit = std::min({limit, firstCrossing(f0, f1, f2, 0.0), firstCrossing(f0, f1, f2, L)});
            continue;
        }
        Vec2 rel0, rel1, rel2;
        double D;
        if (h.body == ContactBody::Ball) {
            const Path& pb = path_[at(h.other)];
            rel0 = pb.c0 - pa.c0;
            rel1 = pb.c1 - pa.c1;
            rel2 = pb.c2 - pa.c2;
            D = touchDistance(radius(h.a), radius(h.other));
        } else {
            const JawTip& jaw = table_.jaws[at(h.other)];
            rel0 = jaw.centre - pa.c0;
            rel1 = -pa.c1;
            rel2 = -pa.c2;
            D = radius(h.a) + jaw.radius;
        }
        const Vec2 n = rel0.normalized();
        const double W = (rel1 - rel1.dot(n) * n).norm();
        const double A = 2.0 * (rel2 - rel2.dot(n) * n).norm();
        // The frozen normal lets the pair's distance grow by |tangential displacement|^2 / (2 D):
        // at most kSegmentGap per segment, and the normal turns by at most kMaxTurn.
        const double target = std::min(kMaxTurn * D, std::sqrt(2.0 * D * kSegmentGap));
        double s = kNever;
        if (A > 0.0) s = (-W + std::sqrt(W * W + 2.0 * A * target)) / A;
        else if (W > 0.0) s = target / W;
        limit = std::min(limit, s);
    }
    return std::max(limit, 1e-9);  // s: a floor, so that solving again always moves time on
}

int Simulator::settle(double t, const std::vector<int>& eventBalls, const std::vector<BallState>& eventStates,
                      const HeldContact* candidate, bool forceHold, double candidateSeparation)
{
    lastGroupSize_ = 0;
    bool touched = candidate != nullptr;
    for (int b : eventBalls) touched = touched || heldCount_[at(b)] > 0;
    if (!touched) return 0;

    // The group: the balls reachable from the event's balls over held contacts, and the candidate.
    std::vector<int> members;
    std::vector<std::size_t> fromHeld;  // indices into held_
    auto addMember = [&](int b) {
        if (std::find(members.begin(), members.end(), b) == members.end()) members.push_back(b);
    };
    for (int b : eventBalls) addMember(b);
    if (candidate) {
        addMember(candidate->a);
        if (candidate->body == ContactBody::Ball) addMember(candidate->other);
    }
    for (std::size_t scan = 0; scan < members.size(); ++scan) {
        const int b = members[scan];
        if (heldCount_[at(b)] == 0) continue;
        for (std::size_t k = 0; k < held_.size(); ++k) {
            const HeldContact& h = held_[k];
            const bool mine = h.a == b || (h.body == ContactBody::Ball && h.other == b);
            if (!mine || std::find(fromHeld.begin(), fromHeld.end(), k) != fromHeld.end()) continue;
            fromHeld.push_back(k);
            addMember(h.a);
            if (h.body == ContactBody::Ball) addMember(h.other);
        }
    }
    std::sort(members.begin(), members.end());
    std::sort(fromHeld.begin(), fromHeld.end());

    std::vector<ContactBall> balls(members.size());
    auto local = [&](int b) {
        return static_cast<int>(std::find(members.begin(), members.end(), b) - members.begin());
    };
    std::vector<std::pair<std::size_t, int>> logged;  // transitions of other members due now: event, ball
    for (std::size_t m = 0; m < members.size(); ++m) {
        const int b = members[m];
        const auto ev = std::find(eventBalls.begin(), eventBalls.end(), b);
        if (ev != eventBalls.end()) {
            balls[m].state = eventStates[static_cast<std::size_t>(ev - eventBalls.begin())];
        } else if (end_[at(b)] <= t) {
            // Its own transition is due at this very instant: it happens first (its event is logged
            // here, so that solving the group now does not swallow it).
            Event tr;
            tr.time = t;
            tr.balls[0] = b;
            tr.before[0] = stateNow(b, t);
            tr.after[0] = applyTransition(state_[at(b)], radius(b), p_, push_[at(b)]);
            balls[m].state = tr.after[0];
            if (pushedTransitionKind(state_[at(b)].motion, tr.after[0].motion, tr.kind)) {
                logged.emplace_back(r_.events.size(), b);
                r_.events.push_back(tr);
            }
        } else {
            balls[m].state = stateNow(b, t);
        }
        balls[m].radius = radius(b);
        balls[m].mass = mass(b);
    }

    // The contacts that still hold: touching (within kHeldGap), no faster normal relative speed than
    // kHoldSpeed, nobody pocketed. What normal relative speed the held contacts have left (the frozen
    // normal of a push off the line of centres, or the group's other events) is taken away by normal
    // impulses at the contacts, all together ("re-seating", Contact.h: seatContacts; it only removes
    // energy).
    std::vector<HeldContact> contacts;
    std::vector<ContactLink> links;
    std::vector<double> normalSpeeds;
    auto consider = [&](const HeldContact& h, bool isCandidate) {
        const BallState& sa = balls[at(local(h.a))].state;
        if (sa.motion == MotionState::Pocketed) return;
        ContactLink link;
        link.a = local(h.a);
        double gap = 0.0, vn = 0.0;
        if (h.body == ContactBody::Ball) {
            const BallState& sb = balls[at(local(h.other))].state;
            if (sb.motion == MotionState::Pocketed) return;
            const Vec2 d = sb.position - sa.position;
            link.b = local(h.other);
            link.normal = d.normalized();
            gap = d.norm() - touchDistance(radius(h.a), radius(h.other));
            vn = (sb.velocity - sa.velocity).dot(link.normal);
        } else if (h.body == ContactBody::Cushion) {
            const CushionSegment& seg = table_.cushions[at(h.other)];
            link.normal = -seg.normal;
            gap = (sa.position - seg.a).dot(seg.normal) - radius(h.a);
            vn = -sa.velocity.dot(link.normal);
            const double foot = (sa.position - seg.a).dot((seg.b - seg.a).normalized());
            if (!isCandidate && (foot < 0.0 || foot > (seg.b - seg.a).norm())) return;
        } else {
            const JawTip& jaw = table_.jaws[at(h.other)];
            const Vec2 d = jaw.centre - sa.position;
            link.normal = d.normalized();
            gap = d.norm() - radius(h.a) - jaw.radius;
            vn = -sa.velocity.dot(link.normal);
        }
        if (!isCandidate && (gap > kHeldGap || gap < -1e-9 || std::abs(vn) > kHoldSpeed)) return;  // parted, or struck
        contacts.push_back(h);
        links.push_back(link);
        normalSpeeds.push_back(vn);
    };
    for (std::size_t k : fromHeld) consider(held_[k], false);
    if (candidate) consider(*candidate, true);

    lastGroupSize_ = links.size() + (members.size() - eventBalls.size());  // contacts, and others re-segmented
    bool seat = false;
    for (double vn : normalSpeeds) seat = seat || std::abs(vn) > 1e-14;  // m/s: rounding is left alone
    if (seat) seatContacts(balls, links, normalSpeeds);
    ContactSolution sol;
    if (!links.empty()) sol = solveContacts(balls, links, p_);
    bool seatedOnly = false;
    (void)candidateSeparation;
    if (candidate) {
        const bool pressed = !links.empty() && contacts.back() == *candidate && sol.active.back();
        // A resting candidate (no approach, up to kRestingSpeed, or a law that does not part the
        // bodies) is held even when the solve does not press it (with no force: its bodies part as
        // they will), so that it cannot be found again and again at one instant; the next solve
        // releases it.
        if (!pressed && !forceHold) {
            // A pair on its own keeps its law's result. In a held group the candidate (parting slower
            // than kHoldSpeed) is seated with the others instead, its separation taken away as theirs
            // are: micro-bounces inside a pressed group are inelastic, and re-seating the others
            // cannot drive it back in at this instant (a ball wedged between a rail and a jaw). It is
            // not held; the next solve sees it as any touching pair.
            if (fromHeld.empty()) return 2;
            seatedOnly = true;
        } else if (!links.empty() && contacts.back() == *candidate) {
            sol.active.back() = 1;
        }
    }

    // Commit: the group's contacts are replaced by those that are active.
    for (std::size_t r = fromHeld.size(); r-- > 0;) {
        const HeldContact& h = held_[fromHeld[r]];
        --heldCount_[at(h.a)];
        if (h.body == ContactBody::Ball) --heldCount_[at(h.other)];
        held_.erase(held_.begin() + static_cast<std::ptrdiff_t>(fromHeld[r]));
    }
    std::vector<HeldContact> kept;
    auto still = [&](int m) {  // the ball neither moves nor is pushed into motion
        if (m < 0) return true;
        const std::size_t q = at(m);
        const MotionState label = sol.label.empty() ? balls[q].state.motion : sol.label[q];
        return (label == MotionState::Stationary || label == MotionState::Spinning) && (sol.push.empty() || sol.push[q].isZero(0.0));
    };
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        if (!links.empty() && still(links[k].a) && still(links[k].b)) continue;  // nothing to hold
        const bool isCandidate = candidate && k + 1 == contacts.size() && contacts[k] == *candidate;
        const bool resting = !isCandidate && sol.accel[k] <= kRestingAcceleration;
        if (!sol.converged || !(sol.active[k] || resting)) continue;
        kept.push_back(contacts[k]);
        held_.push_back(contacts[k]);
        ++heldCount_[at(contacts[k].a)];
        if (contacts[k].body == ContactBody::Ball) ++heldCount_[at(contacts[k].other)];
    }
    for (std::size_t m = 0; m < members.size(); ++m) {
        const int b = members[m];
        BallState s = balls[m].state;
        Vec2 push = Vec2::Zero();
        if (!links.empty() && sol.converged && heldCount_[at(b)] > 0 && s.motion != MotionState::Pocketed) {
            push = sol.push[m];
            s.motion = sol.label[m];
        }
        state_[at(b)] = s;
        push_[at(b)] = push;
        path_[at(b)] = pathOf(s, radius(b), p_, push);
    }
    bool pushed = false;
    for (int b : members) pushed = pushed || !push_[at(b)].isZero(0.0);
    const double limit = pushed ? t + turnLimit(members, kept, t) : kNever;
    for (std::size_t m = 0; m < members.size(); ++m) {
        const int b = members[m];
        regroupAt_[at(b)] = heldCount_[at(b)] > 0 ? limit : kNever;
        beginSegment(b, t, state_[at(b)], push_[at(b)]);
    }
    for (int b : members) predictOwn(b, t);
    for (int b : members) predictPairs(b, t);
    for (const auto& [index, b] : logged) {
        r_.events[index].after[0] = state_[at(b)];
        r_.events[index].grouped = true;
    }
    return seatedOnly ? 3 : 1;
}

void Simulator::finishEvent(double t, const Event& e)
{
    r_.events.push_back(e);
    bool held = false;
    for (std::size_t k = 0; k < 2; ++k) held = held || (e.balls[k] >= 0 && heldCount_[at(e.balls[k])] > 0);
    if (!held) {  // the common case: no push involved, no group to solve
        for (std::size_t k = 0; k < 2; ++k)
            if (e.balls[k] >= 0) beginSegment(e.balls[k], t, e.after[k]);
        for (std::size_t k = 0; k < 2; ++k)
            if (e.balls[k] >= 0) predictOwn(e.balls[k], t);
        for (std::size_t k = 0; k < 2; ++k)
            if (e.balls[k] >= 0) predictPairs(e.balls[k], t);
        return;
    }
    std::vector<int> balls;
    std::vector<BallState> states;
    for (std::size_t k = 0; k < 2; ++k)
        if (e.balls[k] >= 0) {
            balls.push_back(e.balls[k]);
            states.push_back(e.after[k]);
        }
    const std::size_t index = r_.events.size() - 1;
    if (settle(t, balls, states, nullptr, false) == 1) {
        for (std::size_t k = 0; k < balls.size(); ++k) r_.events[index].after[k] = state_[at(balls[k])];
        r_.events[index].grouped = lastGroupSize_ > 0;
        return;
    }
    for (std::size_t k = 0; k < balls.size(); ++k) beginSegment(balls[k], t, states[k]);
    for (int b : balls) predictOwn(b, t);
    for (int b : balls) predictPairs(b, t);
}

void Simulator::process(const Candidate& c)
{
    const double t = c.time;
    const int i = c.ball;
    if (c.agent == Agent::Refresh) {
        if (c.index == 1) {  // a held group is solved again (no event)
            if (settle(t, {i}, {stateNow(i, t)}, nullptr, false) == 0) {
                regroupAt_[at(i)] = kNever;
                predictOwn(i, t);
                predictPairs(i, t);
            }
            return;
        }
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
        const Vec2 push = push_[at(i)];
        if (!push.isZero(0.0)) {
            // The end of a pushed state: an event when the ball's motion changes, then the group is
            // solved again either way.
            const BallState after = applyTransition(state_[at(i)], radius(i), p_, push);
            EventKind kind = EventKind::SlideToRoll;
            if (pushedTransitionKind(state_[at(i)].motion, after.motion, kind)) {
                e.kind = kind;
                e.after[0] = after;
                finishEvent(t, e);
                return;
            }
            if (settle(t, {i}, {after}, nullptr, false) == 0) {
                beginSegment(i, t, after);
                predictOwn(i, t);
                predictPairs(i, t);
            }
            return;
        }
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
        HeldContact candidate{i, ContactBody::Cushion, c.index};
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
            candidate.body = ContactBody::Jaw;
        }
        CushionResult res = resolveCushion(e.before[0], normal, radius(i), mass(i), table_.cushionHeight, p_);
        res.after.motion = classify(res.after, radius(i));
        e.after[0] = res.after;
        e.contactPoint = e.before[0].position - radius(i) * normal;
        e.normal = -normal;
        e.approachSpeed = res.approachSpeed;
        e.impulse = res.impulse;
        const double separation = res.after.velocity.dot(normal);
        if (separation < kHoldSpeed) {
            Event h = e;
            h.after[0].velocity -= separation * normal;
            h.after[0].motion = classify(h.after[0], radius(i));
            h.impulse.head<2>() -= (mass(i) * separation) * normal;
            h.held = true;
            h.holdImpulse = mass(i) * separation;
            const std::size_t index = r_.events.size();
            r_.events.push_back(h);
            // Forced when the approach was nil or the law does not even part them: then holding is the
            // only way not to meet again at this instant.
            const bool force = e.approachSpeed <= kRestingSpeed || separation <= kRestingSpeed;
            const int settled = settle(t, {i}, {h.after[0]}, &candidate, force, separation);
            if (settled == 1 || settled == 3) {
                Event& logged = r_.events[index];
                logged.after[0] = state_[at(i)];
                logged.grouped = lastGroupSize_ > 1;
                if (settled == 3) logged.held = false;
                return;
            }
            r_.events.pop_back();
        }
        break;
    }
    case Agent::Ball: {
        const int j = c.index;
        e.kind = EventKind::BallBall;
        e.balls[1] = j;
        e.before[1] = stateNow(j, t);
        BallBallResult res = resolveBallBall({e.before[0], radius(i), mass(i)}, {e.before[1], radius(j), mass(j)}, p_);
        res.a.motion = classify(res.a, radius(i));
        res.b.motion = classify(res.b, radius(j));
        e.after[0] = res.a;
        e.after[1] = res.b;
        e.contactPoint = res.contactPoint;
        e.normal = res.normal;
        e.approachSpeed = res.approachSpeed;
        e.impulse = res.impulse;
        const double separation = (res.b.velocity - res.a.velocity).dot(res.normal);
        if (separation < kHoldSpeed) {
            Event h = e;
            const double extra = separation / (1.0 / mass(i) + 1.0 / mass(j));  // N s
            h.after[0].velocity += (extra / mass(i)) * res.normal;
            h.after[1].velocity -= (extra / mass(j)) * res.normal;
            h.after[0].motion = classify(h.after[0], radius(i));
            h.after[1].motion = classify(h.after[1], radius(j));
            h.impulse.head<2>() += extra * res.normal;
            h.held = true;
            h.holdImpulse = extra;
            const std::size_t index = r_.events.size();
            r_.events.push_back(h);
            const HeldContact candidate{i, ContactBody::Ball, j};
            const bool force = e.approachSpeed <= kRestingSpeed || separation <= kRestingSpeed;
            const int settled = settle(t, {i, j}, {h.after[0], h.after[1]}, &candidate, force, separation);
            if (settled == 1 || settled == 3) {
                Event& logged = r_.events[index];
                logged.after[0] = state_[at(i)];
                logged.after[1] = state_[at(j)];
                logged.grouped = lastGroupSize_ > 1;
                if (settled == 3) logged.held = false;
                return;
            }
            r_.events.pop_back();
        }
        break;
    }
    }
    finishEvent(t, e);
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
    long long steps = 0;  // events and internal refreshes: a bound on the loop whatever happens
    for (;;) {
        const Candidate c = queue_.top();
        if (c.time == kNever || c.time > limit_) break;
        if (static_cast<long long>(r_.events.size()) >= maxEvents_ || ++steps > 50 * maxEvents_ + 1000) {
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
    if (!it->push.isZero(0.0)) return segmentState(*it, R, physics, t - it->start);  // a held push
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

BallState segmentState(const MotionSegment& seg, double radius, const PhysicsParams& p, double dt)
{
    return evolve(seg.state, radius, p, dt, seg.push);
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
