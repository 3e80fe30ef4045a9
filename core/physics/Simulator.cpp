// The event loop (issue 3): next event -> evolve its agents to its time -> resolve it -> re-predict
// only the balls it involved. Balls evolve lazily: each keeps the start time and state of its
// current motion segment, and everything it will do is predicted from that segment's closed form.
// The groups of held contacts (a push) are in HeldContacts.cpp.

#include "Simulator.h"

#include "ContactTrace.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

namespace cuelab::detail {

Path Simulator::pathNow(int i, double t) const
{
    // The segment's polynomial shifted to the origin t: p(tau0 + s) expanded in s.
    return path_[at(i)].shifted(t - start_[at(i)]);
}

bool Simulator::atRest(int i) const
{
    const MotionState m = state_[at(i)].motion;
    return m == MotionState::Stationary || isOutOfPlay(m);
}

void Simulator::noteStop(MotionState was, MotionState is, double t)
{
    if ((was == MotionState::Sliding || was == MotionState::Rolling) && (is == MotionState::Stationary || is == MotionState::Spinning))
        lastStop_ = std::max(lastStop_, t);
}

void Simulator::beginSegment(int i, double t, const BallState& s, const Vec2& push)
{
    BallState st = s;
    const bool free = push.isZero(0.0);
    if (free && !isOutOfPlay(st.motion)) st.motion = classify(st, radius(i));
    if (st.motion != MotionState::Airborne && !isOutOfPlay(st.motion)) {
        // On the cloth: exactly no height (a ball left a rounding above it, or about to be answered
        // by it, is simply on it).
        st.z = 0.0;
        st.vz = 0.0;
    }
    series_[at(i)] = 0;
    noteStop(state_[at(i)].motion, st.motion, t);
    start_[at(i)] = t;
    state_[at(i)] = st;
    push_[at(i)] = push;
    pushZ_[at(i)] = 0.0;
    path_[at(i)] = pathOf(st, radius(i), p_, push);
    const Transition tr = nextTransition(st, radius(i), p_, push);
    end_[at(i)] = tr.after == kNever ? kNever : t + tr.after;
    box_[at(i)] = boxOf(path_[at(i)], std::min(tr.after, regroupAt_[at(i)] - t));
    r_.timelines[at(i)].push_back(MotionSegment{t, st, push, heldCount_[at(i)] > 0});
}

void Simulator::predictOwn(int i, double now)
{
    Candidate best;
    best.ball = i;
    const BallState& s = state_[at(i)];
    const Path p = pathNow(i, now);
    window_[at(i)] = boxOf(p, 0.0);
    horizon_[at(i)] = end_[at(i)];
    if (isOutOfPlay(s.motion)) {
        own_[at(i)] = best;
        grid_.remove(i);
        return;
    }
    if (series_[at(i)]) {  // its only own event is its end; pairs near it split it (seriesPairTime)
        best = Candidate{end_[at(i)], 0, i, Agent::Transition, 0};
        own_[at(i)] = best;
        window_[at(i)] = box_[at(i)];
        Box grown = box_[at(i)];
        grown.lo.array() -= radius(i);
        grown.hi.array() += radius(i);
        grid_.place(i, grown);
        return;
    }
    if (end_[at(i)] != kNever) best = Candidate{end_[at(i)], 0, i, Agent::Transition, 0};
    // A held group is solved again before a frozen direction turns too far (Refresh, index 1).
    // (Index 2: a hold in the air is solved again, AirHold.cpp.)
    if (regroupAt_[at(i)] < best.time) best = Candidate{regroupAt_[at(i)], 0, i, Agent::Refresh, airHeldAny(i) ? 2 : 1};
    const bool moving = s.motion == MotionState::Sliding || s.motion == MotionState::Rolling || s.motion == MotionState::Airborne;
    if (moving) {
        const double horizon = end_[at(i)] - now;
        const double R = radius(i);
        const Box& box = box_[at(i)];
        auto consider = [&](double ds, int category, Agent agent, int index) {
            if (ds == kNever) return;
            const Candidate c{now + ds, category, i, agent, index};
            if (earlier(c, best)) best = c;
        };
        if (s.motion == MotionState::Airborne) {
            predictAirContacts(i, now, p, best);
        } else {
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
        }
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
    if (isOutOfPlay(a.motion) || isOutOfPlay(b.motion)) return kNever;
    if (series_[at(i)] || series_[at(j)]) return seriesPairTime(i, j, now);
    if (airHeld_[at(i)] == j) return kNever;  // held together in the air
    if (a.motion == MotionState::Airborne || b.motion == MotionState::Airborne) {
        if (heldCount_[at(i)] > 0 && heldCount_[at(j)] > 0 && heldPair(i, j)) return kNever;  // held together in a group
        return airPairTime(i, j, now);
    }
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
    if (!isOutOfPlay(state_[at(i)].motion)) {
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
    if (settle(t, balls, states, nullptr, false) == Settled::Held) {
        for (std::size_t k = 0; k < balls.size(); ++k) r_.events[index].after[k] = state_[at(balls[k])];
        r_.events[index].grouped = lastGroupSize_ > 0;
        r_.events[index].group = lastGroupChanges_;
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
        if (c.index == 2) {  // a hold in the air is solved again (no event)
            const int other = airHeld_[at(i)], edge = airEdge_[at(i)];
            if (other >= 0 && !airHold(flying(i) ? i : other, flying(i) ? other : i, t)) airRelease(i, t);
            const int cushions = static_cast<int>(table_.cushions.size());
            if (edge >= 0 && !(edge < cushions ? airEdgeHold(i, edge, t, stateNow(i, t)) : airRimHold(i, edge - cushions, t, stateNow(i, t))))
                airRelease(i, t);
            if (other < 0 && edge < 0) {
                regroupAt_[at(i)] = kNever;
                predictOwn(i, t);
                predictPairs(i, t);
            }
            return;
        }
        if (c.index == 1) {  // a held group is solved again (no event)
            if (settle(t, {}, {}, nullptr, false, i) == Settled::Untouched) {
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
    // An event of a ball held in the air ends the hold first: the event's balls keep their segments
    // (the event ends them: a landing, the pushed ball's transition, a collision), the other ball goes
    // on freely from its state then (no event). Still pressed, the pair is met again at once.
    if (airHeldAny(i) || (c.agent == Agent::Ball && airHeldAny(c.index))) {
        const int other = c.agent == Agent::Ball ? c.index : -1;
        if (airHeldAny(i)) airRelease(i, t, i, other);
        if (other >= 0 && airHeldAny(other)) airRelease(other, t, i, other);
    }
    if (c.agent == Agent::Ball && (series_[at(i)] || series_[at(c.index)])) {
        // Another ball may come near a bounce series: it goes on one flight at a time, whose
        // contacts are found exactly (no event: the motion goes on unchanged).
        if (series_[at(i)]) splitSeries(i, t);
        if (series_[at(c.index)]) splitSeries(c.index, t);
        return;
    }
    if (c.agent == Agent::Transition && series_[at(i)]) {
        endSeries(i, t);
        return;
    }
    if (c.agent == Agent::Transition && flying(i)) {
        land(i, t);
        return;
    }
    Event e;
    e.time = t;
    e.balls[0] = i;
    e.before[0] = stateNow(i, t);
    if ((c.agent == Agent::Cushion || c.agent == Agent::Jaw) && flying(i)) {
        airCushion(c, e);
        return;
    }
    if (c.agent == Agent::Ball && (flying(i) || flying(c.index))) {
        airBallBall(c, e);
        return;
    }
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
            if (settle(t, {i}, {after}, nullptr, false, -1, true) == Settled::Untouched) {
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
        if (separation < kHoldSpeed && holdCollision(e, candidate, separation)) return;
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
        if (separation < kHoldSpeed && holdCollision(e, HeldContact{i, ContactBody::Ball, j}, separation)) return;
        break;
    }
    }
    finishEvent(t, e);
}

bool Simulator::holdCollision(const Event& e, const HeldContact& candidate, double separation)
{
    // The law leaves the bodies parting slower than kHoldSpeed: settle() decides with the group they
    // touch whether the forces press them (then the pair is held and its separation taken away) or
    // not (then the law's result stands, re-seated with the group if there is one).
    const std::size_t index = r_.events.size();
    r_.events.push_back(e);
    std::vector<int> balls;
    std::vector<BallState> states;
    for (std::size_t k = 0; k < 2; ++k)
        if (e.balls[k] >= 0) {
            balls.push_back(e.balls[k]);
            states.push_back(e.after[k]);
        }
    // Forced when the approach was nil or the law does not even part them: then holding is the only
    // way not to meet again at this instant.
    const bool force = e.approachSpeed <= kRestingSpeed || separation <= kRestingSpeed;
    const Settled settled = settle(e.time, balls, states, &candidate, force);
    if (settled != Settled::Held && settled != Settled::SeatedOnly) {
        r_.events.pop_back();
        return false;
    }
    Event& logged = r_.events[index];
    for (std::size_t k = 0; k < balls.size(); ++k) logged.after[k] = state_[at(balls[k])];
    logged.held = settled == Settled::Held;
    logged.holdImpulse = -lastCandidateImpulse_;
    logged.impulse.head<2>() -= lastCandidateImpulse_ * e.normal;
    logged.grouped = lastGroupSize_ > 1;
    logged.group = lastGroupChanges_;
    return true;
}

void Simulator::stopUnfinished(SimulationStatus status, double lastEvent, const std::string& why)
{
    // Cut short (the event cap) or cancelled: the events and the segments begun so far stand, and
    // the result says the run ended at its last event with balls still moving.
    r_.status = status;
    r_.endTime = lastEvent;
    r_.error = why;
}

void Simulator::run(const std::optional<CueStrike>& shot)
{
    for (int i = 0; i < n_; ++i) beginSegment(i, 0.0, r_.balls[at(i)].state);

    if (shot) {
        const int i = r_.ballIndex(shot->ball);
        if (i >= 0 && !isOutOfPlay(state_[at(i)].motion)) strike(i, *shot);
    }
    for (int i = 0; i < n_; ++i) predictOwn(i, 0.0);
    for (int i = 0; i < n_; ++i) predictPairs(i, 0.0);

    double lastEvent = 0.0;
    long long steps = 0;  // events and internal refreshes: a bound on the loop whatever happens
    using Clock = std::chrono::steady_clock;
    const auto interval = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(progressInterval_));
    auto nextReport = Clock::now();
    for (;;) {
        const Candidate c = queue_.top();
        if (c.time == kNever || c.time > limit_) break;
        // The clock is read every 64 steps (a step takes microseconds; a report is due every tenth of
        // a second or so).
        if (progress_ && (steps & 63) == 0 && Clock::now() >= nextReport) {
            r_.status = SimulationStatus::Running;
            r_.endTime = lastEvent;
            progress_(r_, SimulationProgress{static_cast<long long>(r_.events.size()), steps, lastEvent});
            nextReport = Clock::now() + interval;
        }
        if (cancel_.stop_requested()) {
            std::ostringstream msg;
            msg << "the simulation was cancelled at t = " << lastEvent << " s after " << r_.events.size() << " events";
            stopUnfinished(SimulationStatus::Cancelled, lastEvent, msg.str());
            return;
        }
        const bool eventCap = static_cast<long long>(r_.events.size()) >= maxEvents_;
        if (eventCap || ++steps > 50 * maxEvents_ + 1000) {
            std::ostringstream msg;
            if (eventCap)
                msg << "the simulation stopped after " << maxEvents_ << " events at t = " << lastEvent
                    << " s with balls still moving (event limit reached)";
            else
                msg << "the simulation stopped after " << (steps - 1) << " steps (" << r_.events.size()
                    << " events and the internal re-predictions between them, at most 50 per allowed event) at t = "
                    << lastEvent << " s with balls still moving (event limit reached)";
            stopUnfinished(SimulationStatus::EventLimit, lastEvent, msg.str());
            return;
        }
        if (heldTrace_ && heldTrace_->done) break;  // (a trace of one event: recorded, ContactTrace.h)
        const std::size_t logged = r_.events.size();
        process(c);
        // (A group solved again may log a member's transition or stop: an event too.)
        if (c.agent != Agent::Refresh || r_.events.size() > logged) lastEvent = c.time;
    }
    bool rest = true;
    for (int i = 0; i < n_; ++i) rest = rest && atRest(i);
    if (rest) {
        r_.status = SimulationStatus::AllAtRest;
        // When the last ball came to rest: the last event, or a later solve of a held group that
        // found a ball still (its stop was due a rounding later, and takes no event of its own).
        r_.endTime = r_.events.empty() ? 0.0 : std::max(lastEvent, lastStop_);
    } else {
        r_.status = SimulationStatus::ReachedUntil;
        r_.endTime = limit_;
    }
}


}  // namespace cuelab::detail
