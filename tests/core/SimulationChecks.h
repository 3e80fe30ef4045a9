#pragma once
// Shared checks of whole simulation results for the core test suites: overlaps, balls on the
// table, momentum, energy, and the continuity of the timelines.

#include "BallContact.h"
#include "Contact.h"
#include "Motion.h"
#include "Simulation.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace cuelab::testing {

inline Ball ballAt(const Table& table, const std::string& id, const Vec2& position, const Vec2& velocity = Vec2::Zero(),
                   const Vec3& spin = Vec3::Zero())
{
    Ball b;
    b.id = id;
    b.radius = table.ballRadius;
    b.mass = table.ballMass;
    b.state.position = position;
    b.state.velocity = velocity;
    b.state.spin = spin;
    b.state.motion = classify(b.state, b.radius);
    return b;
}

// The deepest overlap (m) of a ball of radius R at p with the straight cushion noses and the jaw
// tips of the table; <= 0 when it touches none. A cushion counts wherever the foot of the
// perpendicular lies on its segment, however far behind its nose the centre is: a ball that has
// tunnelled through a rail is an overlap of more than R, not a ball "in a mouth".
inline double cushionOverlap(const Table& t, double x, double y, double R)
{
    double worst = -1.0;
    for (const CushionSegment& c : t.cushions) {
        const double ax = c.a.x(), ay = c.a.y(), bx = c.b.x() - ax, by = c.b.y() - ay;
        const double lambda = ((x - ax) * bx + (y - ay) * by) / (bx * bx + by * by);
        if (lambda < 0.0 || lambda > 1.0) continue;
        const double d = (x - ax) * c.normal.x() + (y - ay) * c.normal.y();
        worst = std::max(worst, R - d);
    }
    for (const JawTip& j : t.jaws) {
        const double dx = x - j.centre.x(), dy = y - j.centre.y();
        worst = std::max(worst, R + j.radius - std::sqrt(dx * dx + dy * dy));
    }
    return worst;
}

// The largest overlap (m) between two balls or a ball and a cushion nose or jaw in the states s;
// <= 0 when nothing overlaps.
inline double maxOverlap(const SimulationResult& r, const std::vector<BallState>& s)
{
    // Plain doubles rather than Eigen expressions: this runs at every event of thousands of runs,
    // also in unoptimised sanitizer builds.
    double worst = -1.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i].motion == MotionState::Pocketed) continue;
        const double R = r.balls[i].radius;
        const double x = s[i].position.x(), y = s[i].position.y();
        for (std::size_t j = i + 1; j < s.size(); ++j) {
            if (s[j].motion == MotionState::Pocketed) continue;
            const double reach = touchDistance(R, r.balls[j].radius);  // 2 sqrt(Ri Rj): centres at Ri, Rj
            const double dx = s[j].position.x() - x, dy = s[j].position.y() - y;
            if (dx * dx + dy * dy < reach * reach) worst = std::max(worst, reach - std::sqrt(dx * dx + dy * dy));
        }
        worst = std::max(worst, cushionOverlap(r.table, x, y, R));
    }
    return worst;
}

inline double maxOverlapAt(const SimulationResult& r, double t) { return maxOverlap(r, r.statesAt(t)); }

// Even-odd point in polygon.
inline bool insidePolygon(const std::vector<Vec2>& poly, const Vec2& p)
{
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const Vec2& a = poly[i];
        const Vec2& b = poly[j];
        if ((a.y() > p.y()) != (b.y() > p.y())
            && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
            in = !in;
    }
    return in;
}

// The mouth of pocket k for a ball of radius R: the region a ball's centre may cross between the
// cloth (centres at least R inside the rail noses) and the pocket circle. Bounded by the two rails'
// last nose points moved R onto the cloth, the rails' ends (the jaws' tangent points), and the two
// facings down to their far ends. Built from the table's own elements: the facings of the pocket
// are the two segments "facing-<pocket>-..." and their jaws' rails end where the facing's jaw is.
inline std::vector<Vec2> mouthPolygon(const Table& t, const Pocket& k, double R)
{
    const std::string suffix = k.id.substr(7);  // "pocket-bl" -> "bl"
    std::vector<const CushionSegment*> facings;
    for (const CushionSegment& c : t.cushions)
        if (c.id.rfind("facing-" + suffix + "-", 0) == 0) facings.push_back(&c);
    if (facings.size() != 2) return {};
    std::vector<Vec2> poly;
    for (int side = 0; side < 2; ++side) {
        const CushionSegment& f = *facings[static_cast<std::size_t>(side)];
        // The rail this facing's jaw ends: the rail whose segment has an end point nearest the facing.
        const CushionSegment* rail = nullptr;
        Vec2 railEnd = Vec2::Zero();
        double best = 1e300;
        for (const CushionSegment& c : t.cushions) {
            if (c.id.rfind("rail-", 0) != 0) continue;
            for (const Vec2& e : {c.a, c.b})
                if ((e - f.a).norm() < best) {
                    best = (e - f.a).norm();
                    rail = &c;
                    railEnd = e;
                }
        }
        if (!rail) return {};
        std::vector<Vec2> part{railEnd + R * rail->normal, railEnd, f.a, f.b};
        if (side == 1) std::reverse(part.begin(), part.end());
        poly.insert(poly.end(), part.begin(), part.end());
    }
    return poly;
}

// Why the state s of a ball of radius R is not a legal place, or "" when it is. Legal is:
//  - pocketed: in the pocket's drop path, which the simulator reduces to its end: the ball sits at
//    the pocket's centre, still, for good (Simulation.cpp writes that state at the pocket event);
//  - not pocketed: on the cloth, its centre at least R - 1e-9 m inside the rail noses (the
//    rectangle [R, L - R] x [R, W - R]) or crossing a pocket's mouth towards the pocket, in no
//    pocket circle (a centre inside one drops at once), and overlapping no cushion nose or jaw by
//    more than 1e-9 m wherever it is.
inline std::string placeProblem(const SimulationResult& r, const BallState& s, double R)
{
    const double tol = 1e-9;
    if (s.motion == MotionState::Pocketed) {
        if (s.pocket < 0 || s.pocket >= int(r.table.pockets.size())) return "pocketed in no pocket";
        if (s.position != r.table.pockets[static_cast<std::size_t>(s.pocket)].centre) return "pocketed off its pocket's centre";
        if (!s.velocity.isZero(0.0) || !s.spin.isZero(0.0)) return "pocketed and still moving";
        return {};
    }
    if (s.pocket != -1) return "a pocket index on a ball on the table";
    const Vec2& p = s.position;
    if (!p.allFinite()) return "not finite";
    for (const Pocket& k : r.table.pockets)
        if ((p - k.centre).norm() < k.radius - tol) return "inside " + k.id + " without dropping";
    if (cushionOverlap(r.table, p.x(), p.y(), R) > tol) return "overlaps a cushion or jaw";
    const bool cloth = p.x() >= R - tol && p.x() <= r.table.length - R + tol && p.y() >= R - tol
                       && p.y() <= r.table.width - R + tol;
    if (cloth) return {};
    for (const Pocket& k : r.table.pockets)
        if (insidePolygon(mouthPolygon(r.table, k, R), p)) return {};
    return "off the cloth and in no pocket's mouth";
}

inline bool onTable(const SimulationResult& r, const BallState& s, double radius) { return placeProblem(r, s, radius).empty(); }

// The same for ball `index` at time t, which also needs the event that pocketed it: a pocketed
// ball must have dropped into that very pocket at or before t.
inline std::string placeProblemAt(const SimulationResult& r, int index, double t, const BallState& s)
{
    std::string why = placeProblem(r, s, r.balls[static_cast<std::size_t>(index)].radius);
    if (!why.empty() || s.motion != MotionState::Pocketed) return why;
    for (const Event& e : r.events)
        if (e.kind == EventKind::BallPocket && e.balls[0] == index && e.pocket == s.pocket && e.time <= t) return {};
    return "pocketed without a pocket event";
}

inline double totalEnergy(const SimulationResult& r, const std::vector<BallState>& s)
{
    double e = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) e += kineticEnergy(s[i], r.balls[i].radius, r.balls[i].mass);
    return e;
}

inline bool sameState(const BallState& a, const BallState& b)
{
    return a.position == b.position && a.velocity == b.velocity && a.spin == b.spin && a.motion == b.motion
           && a.pocket == b.pocket;
}

// Momentum of a ball-ball event: whatever the law (frictionless or frictional, and the hold of a
// push, Contact.h), the impulses between the two balls are equal and opposite, so m1 v1 + m2 v2 in
// the plane is the same before and after. Returns the change (N s); 0 for other events, and for a
// held event whose balls were already held with others: its after-states include the impulses that
// re-seat the group's other contacts (Contact.h: seatContacts), which the pair shares with them.
inline double momentumChange(const SimulationResult& r, const Event& e)
{
    if (e.kind != EventKind::BallBall || e.grouped) return 0.0;
    const double m0 = r.balls[static_cast<std::size_t>(e.balls[0])].mass;
    const double m1 = r.balls[static_cast<std::size_t>(e.balls[1])].mass;
    const Vec2 before = m0 * e.before[0].velocity + m1 * e.before[1].velocity;
    const Vec2 after = m0 * e.after[0].velocity + m1 * e.after[1].velocity;
    return (after - before).norm();
}

// The state reached from `seg` at time t by its own closed-form motion (through the transitions it
// would make on the way, as stateAt does), without looking at any later segment.
inline BallState continued(const SimulationResult& r, int index, const MotionSegment& seg, double t)
{
    const double R = r.balls[static_cast<std::size_t>(index)].radius;
    if (!seg.push.isZero(0.0)) return segmentState(seg, R, r.physics, t - seg.start);  // a held push
    BallState s = seg.state;
    double start = seg.start;
    for (;;) {
        const Transition tr = nextTransition(s, R, r.physics);
        if (tr.after == kNever || start + tr.after > t) break;
        s = applyTransition(s, R, r.physics);
        start += tr.after;
    }
    return evolve(s, R, r.physics, t - start);
}

// Continuity of the timelines, ball by ball: the segment k + 1 begins where segment k's closed-form
// motion has taken the ball by then, in position always and in velocity unless the event that began
// it legitimately changes the velocity (a collision or the cue strike involving this ball; a pocket
// moves it to the pocket's centre). A segment is begun by an event of this ball at its start time,
// in order, except in a held push (Contact.h), whose group is solved again without an event (at
// another ball's event, or when a frozen direction has turned far enough): such a segment must carry
// or end a push, or start at an event's time, and what its velocity may change by is the re-seating
// of the group's contacts, at most kHoldSpeed. Returns "" or what broke (ball, segment, numbers).
inline std::string timelineProblem(const SimulationResult& r, double positionTol = 1e-9, double velocityTol = 1e-9)
{
    constexpr double kSeat = kHoldSpeed;  // m/s (Contact.h)
    // The instants at which a held group was solved: a segment of some ball begins or ends a push
    // there, or an event there held a pair or was solved with a group.
    std::vector<double> groupTimes;
    for (const auto& timeline : r.timelines)
        for (std::size_t k = 0; k < timeline.size(); ++k)
            if (!timeline[k].push.isZero(0.0) || (k > 0 && !timeline[k - 1].push.isZero(0.0)))
                groupTimes.push_back(timeline[k].start);
    for (const Event& e : r.events)
        if (e.held || e.grouped) groupTimes.push_back(e.time);
    std::sort(groupTimes.begin(), groupTimes.end());
    auto grouped = [&](double t) { return std::binary_search(groupTimes.begin(), groupTimes.end(), t); };
    for (std::size_t i = 0; i < r.timelines.size(); ++i) {
        const int index = static_cast<int>(i);
        std::vector<const Event*> mine;
        for (const Event& e : r.events)
            if (e.balls[0] == index || e.balls[1] == index) mine.push_back(&e);
        const std::vector<MotionSegment>& tl = r.timelines[i];
        const std::string who = "ball " + std::to_string(i) + ": ";
        if (tl.empty()) return who + "no timeline";
        if (tl.front().start != 0.0) return who + "the timeline does not begin at 0";
        std::vector<double> times;  // of its events, in order
        for (const Event* e : mine) times.push_back(e->time);
        for (std::size_t k = 0; k + 1 < tl.size(); ++k) {
            const MotionSegment& seg = tl[k + 1];
            const std::string where = who + "segment " + std::to_string(k + 1) + " at t = " + std::to_string(seg.start) + ": ";
            if (seg.start < tl[k].start) return where + "starts before the previous one";
            // Its events at this instant: the segment may belong to any of them.
            const Event* e = nullptr;
            bool kick = false;
            const auto range = std::equal_range(times.begin(), times.end(), seg.start);
            for (auto it = range.first; it != range.second; ++it) {
                const Event* here = mine[static_cast<std::size_t>(it - times.begin())];
                e = e ? e : here;
                kick = kick || isCollision(here->kind) || here->kind == EventKind::CueStrike;
            }
            const bool group = grouped(seg.start);
            if (!e && !group) return where + "begins without an event and outside a held group";
            if (!group) {  // outside a held group, one segment per event of the ball at this instant
                std::size_t segments = 0;
                for (std::size_t q = k + 1; q >= 1 && tl[q].start == seg.start; --q) ++segments;
                if (segments > static_cast<std::size_t>(range.second - range.first))
                    return where + "more segments than events of the ball at this instant";
            }
            const BallState end = continued(r, index, tl[k], seg.start);
            const BallState& begin = seg.state;
            const double dp = (end.position - begin.position).norm();
            const double dv = (end.velocity - begin.velocity).norm();
            if (e && e->kind == EventKind::BallPocket) {
                // It drops where the previous motion had brought it, and then lies in the pocket.
                const double drop = (end.position - e->before[0].position).norm();
                if (drop > positionTol) return where + "drops " + std::to_string(drop) + " m from where it rolled";
                if (begin.motion != MotionState::Pocketed) return where + "a pocket event leaves it on the table";
                continue;
            }
            if (end.motion == MotionState::Pocketed && begin.motion != MotionState::Pocketed)
                return where + "moves again after its pocketing";
            if (dp > positionTol) return where + "jumps " + std::to_string(dp) + " m";
            // A held group's contacts are re-seated when it is solved (Contact.h): at most kHoldSpeed.
            const double allowed = kick ? kNever : group ? kSeat : velocityTol;
            if (dv > allowed)
                return where + "velocity jumps " + std::to_string(dv) + " m/s at a " +
                       (e ? std::string(toString(e->kind)) : std::string("re-solved push"));
        }
        std::size_t at = 1;
        for (const Event* e : mine) {
            while (at < tl.size() && tl[at].start < e->time) ++at;
            if (at >= tl.size() || tl[at].start != e->time) return who + "its " + std::string(toString(e->kind)) + " at t = " + std::to_string(e->time) + " begins no segment";
        }
    }
    return {};
}

}  // namespace cuelab::testing
