// The segments of held groups (Contact.h): which contacts are held (heldPair, heldWall), how long a
// group's frozen directions and normals may be kept before it is solved again (turnLimit), the bound
// on a group solved again without an event (quietFloor, Contact.h's kQuietSolves), and which event a
// pushed state's end is. The groups themselves are solved in HeldContacts.cpp.

#include "Simulator.h"

#include "CircleLimits.h"

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

double Simulator::quietFloor(double t, const std::vector<int>& members, bool quiet)
{
    // The stretch: the most solves in a row without an event of any member, since the earliest such
    // stretch began (a solve with an event ends every member's stretch).
    int solves = 0;
    double since = t;
    if (quiet) {
        for (int b : members)
            if (quietSolves_[at(b)] > 0) {
                solves = std::max(solves, quietSolves_[at(b)]);
                since = std::min(since, quietSince_[at(b)]);
            }
        ++solves;
    }
    for (int b : members) {
        quietSolves_[at(b)] = solves;
        quietSince_[at(b)] = since;
    }
    return solves > kQuietSolves ? (t - since) / kQuietSolves : 0.0;
}

double Simulator::turnLimit(double t, const std::vector<int>& members, const std::vector<HeldContact>& contacts,
                            double accuracyFloor) const
{
    double limit = kMaxHeldSegment;
    const double g = p_.gravity;
    for (int m : members) {
        const BallState& s = state_[at(m)];
        const Vec2& q = push_[at(m)];
        if (q.isZero(0.0) || s.motion == MotionState::Airborne) continue;  // (a flying ball has no cloth friction)
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
        if (!(across > 1e-12 * rate.norm())) continue;
        double turn = den > 0.0 ? kMaxTurn * n0 / den : kNever;  // s: until it turns by kMaxTurn
        {
            // A frozen direction costs at most mu g (turn) ds of velocity (mu_r g rolling, mu_s g
            // sliding): allow up to kTurnSpeedError over the segment (turn ~ across s / n0), but never
            // a turn beyond 1/4 rad (the friction must keep acting against the motion or the slip).
            // (A slip running out under a push turns ever faster: kMaxTurn alone cuts its last
            // stretch into a geometric run of segments, thousands of solves of the group.)
            const double mu = s.motion == MotionState::Rolling ? p_.muRoll : p_.muSlide;
            const double budget = std::sqrt(kTurnSpeedError * n0 / (mu * g * across));
            const double den4 = across - 0.25 * along;
            const double quarter = den4 > 0.0 ? 0.25 * n0 / den4 : kNever;
            turn = std::min(std::max(turn, budget), quarter);
        }
        // A quiet stretch (Contact.h's kQuietSolves): the frozen direction may turn further, up to
        // the pushed transition that ends the segment when the motion along it ends (so its friction
        // still only dissipates); the velocity it costs is at most mu g (pi / 2) per second of it.
        turn = std::max(turn, accuracyFloor);
        limit = std::min(limit, turn);
    }
    // The contacts' geometry from now on: a ball that keeps its segment (idle in settle) has its path
    // from that segment's start, not from t.
    for (const HeldContact& h : contacts) {
        const Path pa = pathNow(h.a, t);
        if (h.body == ContactBody::Cushion) {
            const CushionSegment& seg = table_.cushions[at(h.other)];
            const Vec2 d = seg.b - seg.a;
            const double L = d.norm();
            const Vec2 tHat = d / L;
            // Until the foot leaves the segment: past the tolerance the held geometry (settle) gives
            // up, so a ball held on a rail never rides the rail's line past its end over a mouth.
            const double f0 = (pa.c0 - seg.a).dot(tHat), f1 = pa.c1.dot(tHat), f2 = pa.c2.dot(tHat);
            const double h0 = table_.cushionHeight;
            if (flying(h.a) && spaceNow(h.a, t).c0.z() > h0) {
                // A flying ball on the nose edge (its centre above the nose: settle's geometry): its
                // frozen normal turns about the edge (CircleLimits in the plane across it, as
                // airEdgeHold's), or about the end's top corner (airEdgeGeometry) until the foot comes
                // onto the segment; and until the centre comes down to the nose, where the face takes over.
                const SpacePath sp = spaceNow(h.a, t);
                const Vec3 e(tHat.x(), tHat.y(), 0.0);
                limit = std::min(limit, firstCrossing(sp.c0.z(), sp.c1.z(), sp.c2.z(), h0));
                CircleLimits l;
                if (f0 >= 0.0 && f0 <= L) {
                    auto acrossOf = [&](const Vec3& x) { return Vec3(x - x.dot(e) * e); };
                    const Vec3 edge0(seg.a.x(), seg.a.y(), h0);
                    l = circleLimits<Vec3>(acrossOf(edge0 - sp.c0), acrossOf(-sp.c1), acrossOf(-sp.c2), radius(h.a));
                    limit = std::min({limit, firstCrossing(f0, f1, f2, 0.0), firstCrossing(f0, f1, f2, L)});
                } else {
                    const Vec2 end = f0 < 0.0 ? seg.a : seg.b;
                    l = circleLimits<Vec3>(Vec3(end.x(), end.y(), h0) - sp.c0, -sp.c1, -sp.c2, radius(h.a));
                    limit = std::min(limit, firstCrossing(f0, f1, f2, f0 < 0.0 ? 0.0 : L));
                }
                limit = std::min({limit, l.gap, l.drop});
                continue;
            }
            limit = std::min({limit, firstCrossing(f0, f1, f2, -kContactTolerance), firstCrossing(f0, f1, f2, L + kContactTolerance)});
            if (flying(h.a)) {  // a flying ball's face: until its centre rises to the nose's height
                const SpacePath sp = spaceNow(h.a, t);
                limit = std::min(limit, firstCrossing(sp.c0.z(), sp.c1.z(), sp.c2.z(), h0));
            }
            continue;
        }
        if (h.body == ContactBody::Ball && (flying(h.a) || flying(h.other))) {
            // A flying ball pressed on a ball of the group: the same limits in space.
            const SpacePath sa = spaceNow(h.a, t), sb = spaceNow(h.other, t);
            const CircleLimits l = circleLimits<Vec3>(sb.c0 - sa.c0, sb.c1 - sa.c1, sb.c2 - sa.c2, radius(h.a) + radius(h.other));
            limit = std::min({limit, l.gap, l.drop});
            continue;
        }
        Vec2 rel0, rel1, rel2;
        double D;
        if (h.body == ContactBody::Ball) {
            const Path pb = pathNow(h.other, t);
            rel0 = pb.c0 - pa.c0;
            rel1 = pb.c1 - pa.c1;
            rel2 = pb.c2 - pa.c2;
            D = touchDistance(radius(h.a), radius(h.other));
        } else {
            const JawTip& jaw = table_.jaws[at(h.other)];
            const double h0 = table_.cushionHeight;
            if (flying(h.a) && spaceNow(h.a, t).c0.z() > h0) {
                // A flying ball on the rim (settle's geometry, airRimHold's limits): its frozen normal
                // turns about the rim point (the distance from that point bounds the distance from the
                // rim), the centre stays over the tip's arc, and above the nose (below it the side
                // takes over).
                const SpacePath sp = spaceNow(h.a, t);
                const Vec2 rel = sp.c0.head<2>() - jaw.centre;
                const double rho = rel.norm();
                if (rho > 0.0) {
                    const Vec2 u = rel / rho;
                    const Vec3 rim(jaw.centre.x() + jaw.radius * u.x(), jaw.centre.y() + jaw.radius * u.y(), h0);
                    const CircleLimits l = circleLimits<Vec3>(rim - sp.c0, -sp.c1, -sp.c2, radius(h.a));
                    limit = std::min({limit, l.gap, l.drop});
                }
                for (const Vec2& run : jaw.runs)
                    if (!run.isZero(0.0))
                        limit = std::min(limit, firstCrossing((sp.c0.head<2>() - jaw.centre).dot(run), sp.c1.head<2>().dot(run),
                                                              sp.c2.head<2>().dot(run), 0.0));
                limit = std::min(limit, firstCrossing(sp.c0.z(), sp.c1.z(), sp.c2.z(), h0));
                continue;
            }
            rel0 = jaw.centre - pa.c0;
            rel1 = -pa.c1;
            rel2 = -pa.c2;
            D = radius(h.a) + jaw.radius;
            // Until the contact leaves the tip's arc: the frozen normal would carry the ball on
            // along the circle's tangent into the rail nose or the facing (seed37-shot201998).
            for (const Vec2& run : jaw.runs)
                if (!run.isZero(0.0))
                    limit = std::min(limit, firstCrossing(-rel0.dot(run), pa.c1.dot(run), pa.c2.dot(run), kContactTolerance));
            if (flying(h.a)) {  // a flying ball's jaw side: until its centre rises to the nose's height
                const SpacePath sp = spaceNow(h.a, t);
                limit = std::min(limit, firstCrossing(sp.c0.z(), sp.c1.z(), sp.c2.z(), table_.cushionHeight));
            }
        }
        const CircleLimits l = circleLimits<Vec2>(rel0, rel1, rel2, D);
        // (A quiet stretch: the frozen normal may turn further and the distance grow by more than
        // kSegmentGap; it only grows, and past kHeldGap the pair is let go.)
        limit = std::min(limit, std::max(l.gap, accuracyFloor));
        if (!h.flat) limit = std::min(limit, l.drop);  // (a flat contact's forces allow no curvature)
    }
    return std::max(limit, 1e-9);  // s: a floor, so that solving again always moves time on
}

}  // namespace cuelab::detail
