// Sustained contact in the event loop (Contact.h): the group an event touches, its solve and its
// new segments (settle). Which contacts are held, and how long a frozen segment may last
// (turnLimit), are in HeldSegments.cpp.

#include "Simulator.h"

#include "CircleLimits.h"
#include "ContactTrace.h"

#include <algorithm>
#include <cmath>

namespace cuelab::detail {

Simulator::Settled Simulator::settle(double t, const std::vector<int>& eventBalls,
                                     const std::vector<BallState>& eventStates, const HeldContact* candidate,
                                     bool forceHold, int regroup, bool noEvent)
{
    lastGroupSize_ = 0;
    lastCandidateImpulse_ = 0.0;
    // The explanation's record of this solve (ContactTrace.h); none in a normal run.
    std::optional<HeldGroupTrace> traced;
    if (heldTrace_ && !heldTrace_->done) traced.emplace();
    HeldGroupTrace* trace = traced ? &*traced : nullptr;
    const int eventIndex = static_cast<int>(r_.events.size()) - 1;  // (the event being settled, if any)
    lastGroupChanges_.clear();
    bool touched = candidate != nullptr;
    for (int b : eventBalls) touched = touched || heldCount_[at(b)] > 0;
    touched = touched || (regroup >= 0 && heldCount_[at(regroup)] > 0);
    if (!touched) return Settled::Untouched;

    // The group: the balls reachable from the event's balls over held contacts, and the candidate.
    std::vector<int> members;
    std::vector<std::size_t> fromHeld;  // indices into held_
    auto addMember = [&](int b) {
        if (std::find(members.begin(), members.end(), b) == members.end()) members.push_back(b);
    };
    for (int b : eventBalls) addMember(b);
    if (regroup >= 0) addMember(regroup);
    if (candidate) {
        addMember(candidate->a);
        if (candidate->body == ContactBody::Ball) addMember(candidate->other);
    }
    // A member's state at t as the group sees it: the event's result for the event's balls.
    auto stateAt = [&](int b) {
        const auto ev = std::find(eventBalls.begin(), eventBalls.end(), b);
        return ev != eventBalls.end() ? eventStates[static_cast<std::size_t>(ev - eventBalls.begin())] : stateNow(b, t);
    };
    // The balls touching a member without a held contact, neither approaching nor parting faster
    // than kHoldSpeed, join the group with that contact (`touching`): the group's forces must not
    // push a member into a ball they do not see. Left out, such a contact is met at once by detection
    // as a collision, held, and let go at the next solve when its balls' forces part it: in a frozen
    // cluster set sliding at micrometres a second that cycle repeats at every solve of the group
    // (seed17-shot18364: 15 000 events in 7 us).
    std::vector<HeldContact> touching;
    auto isHeld = [&](int a, int b) { return heldCount_[at(a)] > 0 && heldCount_[at(b)] > 0 && heldPair(a, b); };
    auto candidatePair = [&](int a, int b) {
        return candidate && candidate->body == ContactBody::Ball &&
               ((candidate->a == a && candidate->other == b) || (candidate->a == b && candidate->other == a));
    };
    for (std::size_t scan = 0; scan < members.size(); ++scan) {
        const int b = members[scan];
        for (std::size_t k = 0; k < held_.size() && heldCount_[at(b)] > 0; ++k) {
            const HeldContact& h = held_[k];
            const bool mine = h.a == b || (h.body == ContactBody::Ball && h.other == b);
            if (!mine || std::find(fromHeld.begin(), fromHeld.end(), k) != fromHeld.end()) continue;
            fromHeld.push_back(k);
            addMember(h.a);
            if (h.body == ContactBody::Ball) addMember(h.other);
        }
        const BallState sb = stateAt(b);
        // (A flying member, an event's ball that left the cloth, holds nothing on it: the cloth's
        // contacts are in the plane.)
        if (isOutOfPlay(sb.motion) || sb.motion == MotionState::Airborne) continue;
        Box near{sb.position, sb.position};
        const double reach = 2.0 * radius(b) + kHeldGap;
        near.lo.array() -= reach;
        near.hi.array() += reach;
        std::vector<int> found;
        grid_.forEachNear(b, near, [&](int j) { found.push_back(j); });
        std::sort(found.begin(), found.end());
        for (int j : found) {
            if (isHeld(b, j) || candidatePair(b, j) || airHeld_[at(j)] >= 0) continue;  // (held in the air: AirHold.cpp)
            const HeldContact c{std::min(b, j), ContactBody::Ball, std::max(b, j), -1.0};  // (since: not held yet)
            if (std::find(touching.begin(), touching.end(), c) != touching.end()) continue;
            const BallState sj = stateAt(j);
            if (sj.motion != MotionState::Sliding && sj.motion != MotionState::Rolling) continue;
            const Vec2 d = sj.position - sb.position;
            const double gap = d.norm() - touchDistance(radius(b), radius(j));
            const double vn = (sj.velocity - sb.velocity).dot(d.normalized());
            if (gap > kHeldGap || gap < -1e-9 || vn < -kRestingSpeed || vn > kHoldSpeed) continue;
            touching.push_back(c);
            addMember(j);
        }
    }
    std::sort(members.begin(), members.end());
    std::sort(fromHeld.begin(), fromHeld.end());

    std::vector<ContactBall> balls(members.size());
    auto local = [&](int b) {
        return static_cast<int>(std::find(members.begin(), members.end(), b) - members.begin());
    };
    // The forces are solved for the motion each ball's new segment will have: the label its numbers
    // give (a slip that has as good as ended rolls out), as beginSegment gives a free one.
    // A slip so small that the cloth would end it within kSlipRollOutLength (n0^2 / (2 * 3.5 mu_s g))
    // is rolled out now: left, it cuts the group's segment (its turn, its own end) to nanoseconds, and
    // the group's next solve (re-seating) leaves a new one: seed23-shot12231, a 35-ball group solved
    // every ~1e-8 s. (Not the event's own balls: a collision keeps its pair's momentum, the cloth's
    // impulse would not.)
    auto tiny = [&](std::size_t m, const BallState& st, double radius) {
        return std::find(eventBalls.begin(), eventBalls.end(), members[m]) == eventBalls.end() && slipRollsOut(st, radius, p_);
    };
    auto relabel = [&](std::size_t m) {
        ContactBall& cb = balls[m];
        BallState& st = cb.state;
        if (isOutOfPlay(st.motion) || st.motion == MotionState::Airborne) return;  // (flying: it keeps flying)
        if (st.motion == MotionState::Sliding && (slipHasEnded(st, cb.radius) || tiny(m, st, cb.radius))) rollOut(st, cb.radius);
        st.motion = classify(st, cb.radius);
    };
    std::vector<std::pair<std::size_t, int>> logged;  // transitions of other members due now: event, ball
    for (std::size_t m = 0; m < members.size(); ++m) {
        const int b = members[m];
        const auto ev = std::find(eventBalls.begin(), eventBalls.end(), b);
        if (ev != eventBalls.end()) {
            balls[m].state = eventStates[static_cast<std::size_t>(ev - eventBalls.begin())];
        } else if (end_[at(b)] <= t && !flying(b)) {  // (a flying ball's end is its landing: an event)
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
        relabel(m);
    }

    // A link with a flying ball (ContactLink::nz; only ball-ball links fly).
    auto inSpace = [&](const ContactLink& l) {
        return balls[at(l.a)].state.motion == MotionState::Airborne ||
               (l.b >= 0 && balls[at(l.b)].state.motion == MotionState::Airborne);
    };
    // The contacts that may hold: touching (within kHeldGap), no faster normal relative speed than
    // kHoldSpeed, nobody pocketed (the others are released here), and the candidate.
    std::vector<HeldContact> contacts;
    std::vector<ContactLink> links;
    std::vector<double> normalSpeeds;
    // The geometry of a contact from the group's states: its link (normal, curvature), gap and
    // relative normal speed (> 0 parting). False when a body is pocketed, a cushion's foot has left
    // its segment, or a jaw's contact its arc.
    auto geometry = [&](const HeldContact& h, ContactLink& link, double& gap, double& vn) {
        const BallState& sa = balls[at(local(h.a))].state;
        if (isOutOfPlay(sa.motion)) return false;
        link.a = local(h.a);
        link.b = -1;
        if (h.body == ContactBody::Ball) {
            const BallState& sb = balls[at(local(h.other))].state;
            if (isOutOfPlay(sb.motion)) return false;
            link.b = local(h.other);
            if (sa.motion == MotionState::Airborne || sb.motion == MotionState::Airborne) {
                // A flying ball pressed on a ball of the group (issue 23): the contact in space, its
                // normal tilted (ContactLink::nz).
                const SpaceContact c = spaceContact(sa, radius(h.a), sb, radius(h.other));
                if (!(c.distance > 0.0)) return false;
                link.normal = c.normal.head<2>();
                link.nz = c.normal.z();
                gap = c.gap;
                vn = c.normalSpeed;
                link.curvature = c.curvature();
                return true;
            }
            const Vec2 d = sb.position - sa.position;
            const Vec2 v = sb.velocity - sa.velocity;
            link.normal = d.normalized();
            gap = d.norm() - touchDistance(radius(h.a), radius(h.other));
            vn = v.dot(link.normal);
            link.curvature = separationCurvature(d, v);
            return true;
        }
        if (h.body == ContactBody::Cushion && sa.motion == MotionState::Airborne && radius(h.a) + sa.z > table_.cushionHeight) {
            // A flying ball on a nose edge (issue 23; airEdgeHold's geometry): the contact in space, its
            // normal from the edge to the centre in the plane across the edge, tilted up. The slab's
            // nearest point to a centre above the nose is on its edge (or an end's top corner); below
            // the nose it is on the face (next).
            return airEdgeGeometry(h.a, table_.cushions[at(h.other)], sa, link, gap, vn);
        }
        if (h.body == ContactBody::Cushion) {
            const CushionSegment& seg = table_.cushions[at(h.other)];
            link.normal = -seg.normal;
            gap = (sa.position - seg.a).dot(seg.normal) - radius(h.a);
            vn = -sa.velocity.dot(link.normal);
            link.curvature = 0.0;
            const double foot = (sa.position - seg.a).dot((seg.b - seg.a).normalized());
            // (A flying ball's face, issue 23: the same vertical plane; above the nose, the branch
            // before takes the nose edge.)
            return foot >= -kContactTolerance && foot <= (seg.b - seg.a).norm() + kContactTolerance;  // (as detection)
        }
        const JawTip& jaw = table_.jaws[at(h.other)];
        // A flying ball above the nose: on the jaw's rim (a row of its group when it is also held on
        // a ball, seed16-shot363458; alone, airRimHold holds it).
        if (sa.motion == MotionState::Airborne && radius(h.a) + sa.z > table_.cushionHeight)
            return airRimGeometry(jaw, radius(h.a), table_.cushionHeight, sa, link, gap, vn);
        const Vec2 d = jaw.centre - sa.position;
        link.normal = d.normalized();
        gap = d.norm() - radius(h.a) - jaw.radius;
        vn = -sa.velocity.dot(link.normal);
        link.curvature = separationCurvature(d, -sa.velocity);
        // A flying ball's jaw side (issue 23): the same vertical cylinder, up to the nose's height.
        if (sa.motion == MotionState::Airborne && radius(h.a) + sa.z > table_.cushionHeight + kContactTolerance) return false;
        return onJawArc(jaw, sa.position, kContactTolerance);  // (as detection: past the arc, the piece there)
    };
    auto consider = [&](const HeldContact& h, bool isCandidate) {
        ContactLink link;
        double gap = 0.0, vn = 0.0;
        const bool valid = geometry(h, link, gap, vn);
        if (!isCandidate && (!valid || gap > kHeldGap || gap < -1e-9 || std::abs(vn) > kHoldSpeed)) return;  // parted, or struck
        if (isCandidate && isOutOfPlay(balls[at(link.a)].state.motion)) return;
        contacts.push_back(h);
        links.push_back(link);
        normalSpeeds.push_back(vn);
        if (trace) trace->rows.push_back(HeldRow{h, link, gap, vn, inSpace(link), isCandidate, h.since >= 0.0 && !isCandidate});
    };
    for (std::size_t k : fromHeld) consider(held_[k], false);
    for (const HeldContact& h : touching) consider(h, false);
    if (candidate) {
        HeldContact c = *candidate;
        c.since = t;
        for (const HeldContact& h : held_)
            if (h == c) c.since = h.since, c.pressed = h.pressed;
        consider(c, true);
    }
    const std::size_t candidateLink = candidate && !contacts.empty() && contacts.back() == *candidate ? contacts.size() - 1
                                                                                                      : contacts.size();
    lastGroupSize_ = links.size() + (members.size() - eventBalls.size());  // contacts, and others re-segmented
    if (trace) {
        trace->time = t;
        trace->members = members;
        trace->entering = balls;
    }

    // Which contacts the forces press now (the one test of "pressed", with the curvature term). The
    // candidate is held when pressed, or when holding is forced (no approach, or a law that does not
    // part the bodies: it would be found again at this instant).
    // Each solve begins its pivoting where the last one of these contacts ended (Contact.h's `warm`):
    // the group's previous solve, then this one's previous step.
    std::vector<signed char> lastPressed(links.size());
    for (std::size_t k = 0; k < links.size(); ++k) lastPressed[k] = contacts[k].pressed;
    std::vector<char> heldMask(links.size(), 0);
    if (!links.empty()) {
        const ContactSolution probe = solveContacts(balls, links, p_, ContactForces::Pressed, -1, &lastPressed,
                                                    trace ? &trace->pressedForces : nullptr);
        for (std::size_t k = 0; k < links.size(); ++k) heldMask[k] = lastPressed[k] = probe.active[k];
    }
    bool candidateHeld = false;
    if (candidateLink < links.size()) {
        candidateHeld = heldMask[candidateLink] || forceHold;
        heldMask[candidateLink] = candidateHeld ? 1 : 0;
    }
    if (candidate && !candidateHeld && fromHeld.empty()) return Settled::NotPressed;  // its law stands

    // Re-seating (seatContacts): the held contacts lose the normal speed left by the frozen normal
    // of a push off the line of centres, the group's other events, or the candidate's law; the others
    // are only pushed apart. It never adds energy. A re-seat that would change a ball's velocity by
    // more than kHoldSpeed per contact (nearly parallel normals: a ball wedged at a rail and its jaw)
    // is solved again with every contact pushing only.
    bool seat = false;
    for (double vn : normalSpeeds) seat = seat || std::abs(vn) > 1e-14;  // m/s: rounding is left alone
    std::vector<char> parting(links.size(), 0);
    std::vector<char> seatedThrough(links.size(), 0);  // a touching, unheld contact the re-seating pushed through
    if (seat) {
        const std::vector<ContactBall> before = balls;
        ComplementarityTrace* seatTrace = trace ? &trace->seating : nullptr;
        if (trace) trace->seatingTries = 1;
        Seating seating = seatContacts(balls, links, normalSpeeds, heldMask, seatTrace);
        // Bounded, and never adding energy (a projection cannot, but a nearly singular system's
        // rounding can): otherwise every contact only pushes, and if even that fails the states are
        // left as they are (the contacts that still approach are then met by detection).
        double energyBefore = 0.0;
        for (const ContactBall& cb : before) energyBefore += kineticEnergy(cb.state, cb.radius, cb.mass);
        auto sound = [&] {
            // Solved: every held contact left at rest and none approaching (a nearly singular system,
            // nearly parallel normals, can end with a residue that breaks both).
            for (std::size_t k = 0; k < links.size(); ++k)
                if (seating.after[k] < -kRestingSpeed || (heldMask[k] && seating.after[k] > kRestingSpeed)) return false;
            double energy = 0.0;
            for (std::size_t m = 0; m < balls.size(); ++m) {
                int count = 0;
                for (const ContactLink& l : links) count += (l.a == static_cast<int>(m) || l.b == static_cast<int>(m)) ? 1 : 0;
                if ((balls[m].state.velocity - before[m].state.velocity).norm() > kHoldSpeed * count + 1e-12) return false;
                energy += kineticEnergy(balls[m].state, balls[m].radius, balls[m].mass);
            }
            return energy <= energyBefore * (1.0 + 1e-13);  // (rounding of a projection)
        };
        if (!sound()) {
            balls = before;
            std::fill(heldMask.begin(), heldMask.end(), 0);
            if (candidateLink < links.size() && forceHold) heldMask[candidateLink] = 1;
            seating = seatContacts(balls, links, normalSpeeds, heldMask, seatTrace);
            if (trace) trace->seatingTries = 2;
            if (!sound()) {
                if (trace) trace->seatingTries = 3;
                balls = before;
                std::fill(heldMask.begin(), heldMask.end(), 0);
                std::fill(seating.impulse.begin(), seating.impulse.end(), 0.0);
                seating.after = normalSpeeds;
            }
        }
        for (std::size_t m = 0; m < balls.size(); ++m) {  // (as beginSegment labels a free segment)
            ContactBall& cb = balls[m];
            if (isOutOfPlay(cb.state.motion)) continue;
            cb.state.motion = classify(cb.state, cb.radius);
            if (tiny(m, cb.state, cb.radius)) {  // (the re-seating's residue of a slip)
                if (trace) trace->rolledOut.resize(balls.size()), trace->rolledOut[m] = 1;
                rollOut(cb.state, cb.radius);
                cb.state.motion = classify(cb.state, cb.radius);
            }
        }
        for (std::size_t k = 0; k < links.size(); ++k) {
            parting[k] = !heldMask[k] && seating.after[k] > kRestingSpeed;
            seatedThrough[k] = contacts[k].since < 0.0 && seating.impulse[k] != 0.0;
        }
        if (candidateLink < links.size()) lastCandidateImpulse_ = seating.impulse[candidateLink];
    }
    if (candidateLink < links.size() && !heldMask[candidateLink]) candidateHeld = false;

    // The contacts kept: not parting, and pressed by the forces of the re-seated states (or resting:
    // no force, parting no faster than kRestingAcceleration), and the held candidate.
    // A contact the re-seating left approaching (it was refused: unsound) is let go: detection meets
    // it at once as a collision, never held while its bodies move into each other.
    std::vector<std::size_t> open;  // links neither parting, approaching nor an unheld candidate
    std::vector<char> approaching(links.size(), 0);
    for (std::size_t k = 0; k < links.size(); ++k) {
        double gap = 0.0, vn = 0.0;
        geometry(contacts[k], links[k], gap, vn);  // the curvature of the re-seated velocities
        approaching[k] = vn < -kRestingSpeed;
        if (parting[k] || approaching[k] || (k == candidateLink && !candidateHeld)) continue;
        open.push_back(k);
    }
    std::vector<char> keep(links.size(), 0), stillSkipped(links.size(), 0);
    {
        std::vector<ContactLink> trial;
        std::vector<signed char> trialStart;
        for (std::size_t k : open) trial.push_back(links[k]), trialStart.push_back(lastPressed[k]);
        ContactSolution pressed;
        if (!trial.empty()) pressed = solveContacts(balls, trial, p_, ContactForces::Pressed, -1, &trialStart);
        for (std::size_t r = 0; r < open.size(); ++r) lastPressed[open[r]] = pressed.active[r];
        auto still = [&](int m) {  // the ball neither moves nor is pushed into motion
            if (m < 0) return true;
            const std::size_t q = at(m);
            const MotionState label = pressed.label[q];
            return (label == MotionState::Stationary || label == MotionState::Spinning) && pressed.push[q].isZero(0.0);
        };
        for (std::size_t r = 0; r < open.size(); ++r) {
            const std::size_t k = open[r];
            // Nothing to hold (unless the others' forces move them), but for the contact just met: let
            // go at rest, it would be met again as soon as another contact's forces stir its balls.
            if (k != candidateLink && still(links[k].a) && still(links[k].b)) {
                stillSkipped[k] = 1;
                continue;
            }
            // (A contact that began to be held at this very instant stays held through it: letting
            // it go would only have it met again at the same instant, over and over.)
            // A touching contact that was not held (since < 0) joins only when the forces press it:
            // balls rolling side by side stay apart groups, each solved on its own limits. Or when the
            // re-seating pushed through it: its ball's velocity changed with the group's, so it is
            // the group's (held, its segment may begin without an event of its own), not a ball
            // whose velocity jumped alone (seed31-shot572131: 1.1e-3 m/s, no event, no group).
            const bool wasHeld = contacts[k].since >= 0.0;
            keep[k] = pressed.active[r] || (!wasHeld && seatedThrough[k]) ||
                      (wasHeld && (pressed.accel[r] <= kRestingAcceleration || k == candidateLink || contacts[k].since == t));
        }
    }
    // The held segments' forces are solved with frozen normals (ContactForces::Held), which press
    // harder than the true ones, and a contact let go may part so slowly that it would be back before
    // its gap opens past kContactTolerance: detection (Detection.h) would find such a contact again at
    // once, and it would be found, held and let go over and over. So every contact that detection
    // would find now, on the paths the kept contacts' forces give, is kept too, until none is left
    // (each joins at most once).
    ContactSolution sol;
    std::vector<ContactLink> keptLinks;
    // A held contact whose tangential motion slows so fast that the curvature allowance would end
    // the segment before its normal has turned (or its gap grown) enough to matter is held flat: its
    // forces allow no curvature, so nothing limits the segment for it but the frozen normal. (Else
    // the segments shrink geometrically as the tangential speed runs down: a Zeno run of solves.)
    std::vector<char> flat(links.size(), 0);
    auto flatten = [&] {
        std::vector<Path> paths(members.size());
        for (std::size_t m = 0; m < members.size(); ++m) {
            BallState st = balls[m].state;
            Vec2 push = Vec2::Zero();
            if (!isOutOfPlay(st.motion)) {
                push = sol.push[m];
                st.motion = sol.label[m];
                if (push.isZero(0.0)) st.motion = classify(st, balls[m].radius);
            }
            paths[m] = pathOf(st, balls[m].radius, p_, push);
        }
        bool flattened = false;
        std::size_t r = 0;
        for (std::size_t k = 0; k < links.size(); ++k) {
            if (!keep[k]) continue;
            const HeldContact& h = contacts[k];
            ContactLink& link = keptLinks[r++];
            if (h.body == ContactBody::Cushion || flat[k] || inSpace(link)) continue;  // (in space: turnLimit)
            const Path& pa = paths[at(local(h.a))];
            CircleLimits l;
            if (h.body == ContactBody::Ball) {
                const Path& pb = paths[at(local(h.other))];
                l = circleLimits<Vec2>(pb.c0 - pa.c0, pb.c1 - pa.c1, pb.c2 - pa.c2, touchDistance(radius(h.a), radius(h.other)));
            } else {
                const JawTip& jaw = table_.jaws[at(h.other)];
                l = circleLimits<Vec2>(jaw.centre - pa.c0, -pa.c1, -pa.c2, radius(h.a) + jaw.radius);
            }
            if (l.drop < l.gap) {
                flat[k] = 1;
                link.curvature = 0.0;
                flattened = true;
            }
        }
        const std::vector<signed char> start(sol.active.begin(), sol.active.end());
        if (flattened)
            sol = solveContacts(balls, keptLinks, p_, ContactForces::Held, -1, &start, trace ? &trace->heldForces : nullptr);
    };
    for (;;) {
        keptLinks.clear();
        std::vector<signed char> start;
        for (std::size_t k = 0; k < links.size(); ++k)
            if (keep[k]) {
                keptLinks.push_back(links[k]);
                start.push_back(lastPressed[k]);
                if (flat[k]) keptLinks.back().curvature = 0.0;
            }
        sol = keptLinks.empty() ? ContactSolution{}
                                : solveContacts(balls, keptLinks, p_, ContactForces::Held, -1, &start,
                                                trace ? &trace->heldForces : nullptr);
        if (!keptLinks.empty()) flatten();
        for (std::size_t k = 0, r = 0; k < links.size(); ++k)
            if (keep[k]) lastPressed[k] = sol.active[r++];
        auto pathOfMember = [&](int m) {
            const std::size_t q = at(m);
            BallState st = balls[q].state;
            Vec2 push = Vec2::Zero();
            if (!keptLinks.empty() && !isOutOfPlay(st.motion)) {
                push = sol.push[q];
                st.motion = sol.label[q];
            }
            if (push.isZero(0.0) && !isOutOfPlay(st.motion)) st.motion = classify(st, balls[q].radius);
            return pathOf(st, balls[q].radius, p_, push);
        };
        bool joined = false;
        // A contact left out as still must stay so: if the kept contacts' forces set one of its balls
        // moving, it is kept after all (else it is met at once, left out, met again: a cycle).
        for (std::size_t k = 0; k < links.size(); ++k) {
            if (keep[k] || !stillSkipped[k] || keptLinks.empty()) continue;
            auto moves = [&](int m) {
                if (m < 0) return false;
                const std::size_t q = at(m);
                return !(sol.label[q] == MotionState::Stationary || sol.label[q] == MotionState::Spinning) || !sol.push[q].isZero(0.0);
            };
            if (moves(links[k].a) || moves(links[k].b)) {
                keep[k] = 1;
                joined = true;
            }
        }
        for (std::size_t k = 0; k < links.size(); ++k) {
            if (keep[k] || approaching[k]) continue;
            const HeldContact& h = contacts[k];
            if (inSpace(links[k])) continue;  // (a flying ball let go parts: its forces no longer press it)
            const Path pa = pathOfMember(links[k].a);
            constexpr double kNow = 1e-300;  // s: detection's horizon, "at once"
            double when = kNever;
            if (h.body == ContactBody::Ball)
                when = ballBallTime(pa, radius(h.a), pathOfMember(links[k].b), radius(h.other), kNow);
            else if (h.body == ContactBody::Cushion)
                when = cushionTime(pa, radius(h.a), table_.cushions[at(h.other)], kNow);
            else
                when = jawTime(pa, radius(h.a), table_.jaws[at(h.other)], kNow);
            if (when == 0.0) {
                keep[k] = 1;
                joined = true;
            }
        }
        if (!joined) break;
    }
    std::vector<HeldContact> kept;
    for (std::size_t k = 0; k < links.size(); ++k)
        if (keep[k]) {
            kept.push_back(contacts[k]);
            kept.back().flat = flat[k];
            kept.back().pressed = lastPressed[k];
            if (kept.back().since < 0.0) kept.back().since = t;  // (a touching contact held from now)
        }
    if (candidateLink < links.size()) candidateHeld = keep[candidateLink];  // (kept at rest: nothing to hold)

    // Commit: the group's contacts are replaced by those kept, whose forces (frozen normals) give
    // every ball of the group its pushed segment.
    for (std::size_t r = fromHeld.size(); r-- > 0;) {
        const HeldContact& h = held_[fromHeld[r]];
        --heldCount_[at(h.a)];
        if (h.body == ContactBody::Ball) --heldCount_[at(h.other)];
        held_.erase(held_.begin() + static_cast<std::ptrdiff_t>(fromHeld[r]));
    }
    for (const HeldContact& h : kept) {
        held_.push_back(h);
        ++heldCount_[at(h.a)];
        if (h.body == ContactBody::Ball) ++heldCount_[at(h.other)];
    }
    // A ball of the group that had and keeps no push, and that the re-seating left alone (a wall of
    // the group, or a ball held by resting contacts only), keeps its segment: solving the group again
    // changes nothing of its motion.
    std::vector<char> idle(members.size(), 0);
    auto isEventBall = [&](int b) { return std::find(eventBalls.begin(), eventBalls.end(), b) != eventBalls.end(); };
    auto isLogged = [&](int b) {
        return std::any_of(logged.begin(), logged.end(), [&](const std::pair<std::size_t, int>& l) { return l.second == b; });
    };
    for (std::size_t m = 0; m < members.size(); ++m) {
        const int b = members[m];
        BallState s = balls[m].state;
        Vec2 push = Vec2::Zero();
        double pushZ = 0.0;  // (a flying member's)
        if (!keptLinks.empty() && heldCount_[at(b)] > 0 && !isOutOfPlay(s.motion)) {
            push = sol.push[m];
            pushZ = sol.pushZ[m];
            s.motion = sol.label[m];
        }
        if (push_[at(b)].isZero(0.0) && push.isZero(0.0) && pushZ_[at(b)] == 0.0 && pushZ == 0.0 &&
            std::find(eventBalls.begin(), eventBalls.end(), b) == eventBalls.end()) {
            const BallState now = stateNow(b, t);
            idle[m] = now.motion == s.motion && now.position == s.position && now.velocity == s.velocity && now.spin == s.spin;
        }
        if (idle[m]) continue;
        if (!isEventBall(b) && !isLogged(b)) {
            // The event changes this member too (Event::group): its velocity, spin or label.
            const BallState was = stateNow(b, t);
            if (was.velocity != s.velocity || was.spin != s.spin || was.motion != s.motion || was.vz != s.vz)
                lastGroupChanges_.push_back(Event::GroupChange{b, was, s});
        }
        start_[at(b)] = t;  // (beginSegment below logs it; the limit reads every member's path at t)
        noteStop(state_[at(b)].motion, s.motion, t);
        state_[at(b)] = s;
        push_[at(b)] = push;
        pushZ_[at(b)] = pushZ;
        path_[at(b)] = pathOf(s, radius(b), p_, push);
    }
    bool pushed = false;
    for (int b : members) pushed = pushed || !push_[at(b)].isZero(0.0) || pushZ_[at(b)] != 0.0;
    // (A solve without an event of its own counts towards the group's quiet stretch, Contact.h.)
    const double accuracyFloor = quietFloor(t, members, noEvent || (regroup >= 0 && eventBalls.empty() && candidate == nullptr));
    // (Held contacts without force still turn their normals: the segment is bounded for them too.)
    const double limit = pushed || !kept.empty() ? t + turnLimit(t, members, kept, accuracyFloor) : kNever;
    for (std::size_t m = 0; m < members.size(); ++m) {
        const int b = members[m];
        regroupAt_[at(b)] = heldCount_[at(b)] > 0 ? limit : kNever;
        if (!idle[m] && heldFlight(b)) {  // a flying member held on the group: Flight.h's held flight
            beginHeldFlight(b, t, state_[at(b)], push3(b));
            box_[at(b)] = boxOf(path_[at(b)], std::min(end_[at(b)], regroupAt_[at(b)]) - t);
        } else if (!idle[m]) {
            beginSegment(b, t, state_[at(b)], push_[at(b)]);
        } else {  // its window of predictions ends at its own transition or at the group's next solve
            const double s0 = start_[at(b)];
            box_[at(b)] = boxOf(path_[at(b)], std::min(end_[at(b)], regroupAt_[at(b)]) - s0);
        }
    }
    for (int b : members) predictOwn(b, t);
    for (int b : members) predictPairs(b, t);
    // A member's own transition due now keeps its event (its after-state: the transition alone); what
    // the group's solve then changes of it is listed with the solve's other changes (Event::group), in
    // the event that solved the group, or in the first such transition when the solve had no event of
    // its own.
    for (const auto& [index, b] : logged) {
        Event& own = r_.events[index];
        own.grouped = true;
        const BallState& is = state_[at(b)];
        const BallState& was = own.after[0];
        if (was.velocity != is.velocity || was.spin != is.spin || was.motion != is.motion || was.vz != is.vz)
            lastGroupChanges_.push_back(Event::GroupChange{b, was, is});
    }
    if ((eventBalls.empty() || noEvent) && !logged.empty()) r_.events[logged.front().first].group = lastGroupChanges_;
    if (trace) recordHeldTrace(*trace, eventBalls.empty() || noEvent ? (logged.empty() ? -1 : static_cast<int>(logged.front().first)) : eventIndex,
                               seat, balls, heldMask, keep, idle);
    if (!candidate || candidateHeld) return Settled::Held;
    return Settled::SeatedOnly;
}

}  // namespace cuelab::detail
