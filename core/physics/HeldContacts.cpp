// Sustained contact in the event loop (Contact.h): which contacts are held, the group an event
// touches, its solve and new segments (settle), and how long a frozen segment may last (turnLimit).

#include "Simulator.h"

#include <algorithm>
#include <cmath>

namespace cuelab::detail {

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

namespace {

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


}  // namespace cuelab::detail
