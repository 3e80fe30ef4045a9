// A flying ball held against a ball on the cloth (issue 23; docs/airborne.md, "Held in the air").
//
// A flying ball A that touches a ball B on the cloth with no approach while gravity presses it on
// (it slides down B's side) gets no impulse from any collision law, and detection meets the same
// contact again at the same instant. It is a sustained contact, solved as the cloth's held contacts
// are (Contact.h): over a segment the normal n (from B's centre to A's) is frozen and the contact
// force N along it constant, so A flies on a parabola with the acceleration -g z + (N/m_A) n and B
// moves in Motion.h's pushed motion with -(N/m_B) n_h (the cloth takes the force's vertical part).
// N makes the pair's relative normal acceleration kHeldCurvatureShare of the curvature |v_t|^2 / d
// (AirHoldForce.h solves it, for the simulator and the explanation alike):
//     N (1/m_A + c_B |n_h|^2 / m_B) = g n_z + n_h . a_B - share |v_t|^2 / d,
// with c_B and a_B B's response to a push through its centre and its cloth's friction along its
// frozen direction (sliding: 1, -mu_s g e; rolling: 5/7, -mu_r g d; at rest: it rolls off when
// 5/7 of the push beats mu_r g, else the cloth holds it still: c_B = 0). The distance then grows by
// (1 - share) |v_t|^2 s^2 / (2 d) (never an overlap), the normal force does no positive work, and
// the segment ends at CircleLimits' bounds (the gap and the turn) or B's frozen direction's
// (turnLimit), when the pair is solved again with no event. It lets go when N falls to zero (A
// leaves B's surface, the pendulum's release), the gap passes kHeldGap, or an event of either ball
// comes first (its landing included).
//
// A B that the cloth holds in a group takes A into the group instead (groupHoldable: A's contact is a
// row in space of the group's problem, HeldContacts.cpp, Contact.h's ContactLink::nz).
//
// A collision that leaves A coming down on B parting slower than kHoldSpeed is held too, B's
// micro-bounce dropped (airHoldRule, at the end: the cloth's hold rule in the air).
//
// A ball held on two contacts at once (wedged between two balls, a ball and a rail, a ball and a
// jaw's rim, or two nose edges) is not held pairwise: both contacts are rows in space of one group
// (HeldContacts.cpp), solved together (AirCollisions.cpp's `wedged`, airCushion).
//
// Left out: friction between the balls while held (mu_b about 0.05 against the press).

#include "Simulator.h"

#include "AirHoldForce.h"
#include "CircleLimits.h"

#include <algorithm>
#include <cmath>

namespace cuelab::detail {

// A flying ball on a jaw's rim, the circle of the tip at the nose height h (issue 23; airRimHold's
// geometry): the contact in space with the rim's nearest point, its normal in the plane through the
// jaw's axis and the centre, tilted up; the curvature of the motion on the torus the centre keeps
// (across the rim 1/dist, along it (nh/dist)/rho). False when the centre is over the tip's top (no
// rim there) or past its arc.
bool airRimGeometry(const JawTip& jaw, double R, double h, const BallState& s, ContactLink& link, double& gap, double& vn)
{
    const Vec2 rel = s.position - jaw.centre;
    const double rho = rel.norm();
    if (!(rho > jaw.radius) || !onJawArc(jaw, s.position, kContactTolerance)) return false;
    const Vec2 u = rel / rho;
    const double nh = rho - jaw.radius, w = (R + s.z) - h;
    const double dist = std::hypot(nh, w);
    if (w < 0.0 || !(dist > 0.0)) return false;
    const Vec3 out = (nh / dist) * Vec3(u.x(), u.y(), 0.0) + Vec3(0.0, 0.0, w / dist);
    const Vec3 v = velocity3(s);
    link.normal = -out.head<2>();
    link.nz = -out.z();
    gap = dist - R;
    vn = v.dot(out);
    const Vec3 alongRim(-u.y(), u.x(), 0.0);
    const double vAlong = v.dot(alongRim);
    const Vec3 vAcross = v - vn * out - vAlong * alongRim;
    link.curvature = vAcross.squaredNorm() / dist + vAlong * vAlong * (nh / dist) / rho;
    return true;
}


SpacePath Simulator::spaceNow(int i, double now) const
{
    const double r = radius(i);
    if (!flying(i)) return clothPath(pathNow(i, now), r);
    const BallState s = stateNow(i, now);
    return heldFlight(i) ? heldFlightPath(s, r, p_.gravity, push3(i)) : flightPath(s, r, p_.gravity);
}

bool Simulator::airHoldable(int a, int b, bool onCloth) const
{
    if (!flying(a) || series_[at(a)] || series_[at(b)]) return false;
    const MotionState mb = state_[at(b)].motion;
    if ((mb == MotionState::Airborne && !onCloth) || isOutOfPlay(mb)) return false;
    if (heldCount_[at(a)] > 0 || heldCount_[at(b)] > 0) return false;
    if (airEdge_[at(a)] >= 0 || airEdge_[at(b)] >= 0) return false;
    return (airHeld_[at(a)] < 0 || airHeld_[at(a)] == b) && (airHeld_[at(b)] < 0 || airHeld_[at(b)] == a);
}

bool Simulator::groupHoldable(int a, int b) const
{
    // (b may fly too: two flying balls that touch with no approach, one of them a group's member, are
    // a row in space of that group, solved with its others; left to the law, which gives no impulse,
    // they were met again at that instant until the event cap: seed101-shot186657, shot112464.)
    if (!flying(a) || series_[at(a)] || series_[at(b)] || isOutOfPlay(state_[at(b)].motion)) return false;
    if (airHeldAny(a) || airHeldAny(b)) return false;
    return heldCount_[at(a)] > 0 || heldCount_[at(b)] > 0;
}

void Simulator::beginHeldFlight(int i, double t, const BallState& s, const Vec3& push)
{
    BallState st = s;
    st.motion = MotionState::Airborne;
    series_[at(i)] = 0;
    start_[at(i)] = t;
    state_[at(i)] = st;
    push_[at(i)] = push.head<2>();
    pushZ_[at(i)] = push.z();
    path_[at(i)] = Path{st.position, st.velocity, 0.5 * push.head<2>()};
    const double tl = heldLandingTime(st, p_.gravity, push);
    end_[at(i)] = tl == kNever ? kNever : t + tl;
    MotionSegment seg{t, st, push.head<2>(), true};
    seg.pushZ = push.z();
    r_.timelines[at(i)].push_back(seg);
}

bool Simulator::airHold(int a, int b, double t) { return airHold(a, b, t, stateNow(a, t), stateNow(b, t), false); }

bool Simulator::airHold(int a, int b, double t, BallState sa, BallState sb, bool onCloth)
{
    // (In the air, or on the cloth and leaving it: a ball jumping off the cloth beside a ball whose
    // sliding friction brings it back against it, seed14-shot381639.)
    if (!(sa.z > 0.0 || sa.vz > 0.0) || !airHoldable(a, b, onCloth)) return false;
    // The force and the re-seat (AirHoldForce.h: the explanation derives them with the same call).
    const AirHoldStart start = startAirHold(sa, radius(a), mass(a), sb, radius(b), mass(b), p_);
    if (!start.held) return false;
    const AirHoldForce& f = start.force;
    sa = start.a;
    sb = start.b;
    airHeld_[at(a)] = b;
    airHeld_[at(b)] = a;
    beginHeldFlight(a, t, sa, f.pushA);
    sb.motion = f.labelB;
    beginSegment(b, t, sb, f.pushB);
    r_.timelines[at(b)].back().held = true;
    // The segment: until the frozen normal has turned or opened the gap far enough, or b's frozen
    // direction has turned (turnLimit reads b's new segment), at most kMaxHeldSegment.
    const SpacePath pa = spaceNow(a, t), pb = spaceNow(b, t);
    const CircleLimits l = circleLimits<Vec3>(pb.c0 - pa.c0, pb.c1 - pa.c1, pb.c2 - pa.c2, radius(a) + radius(b));
    const double limit = std::max(std::min({turnLimit(t, {b}, {}), l.gap, l.drop}), 1e-9);
    regroupAt_[at(a)] = regroupAt_[at(b)] = t + limit;
    for (int k : {a, b}) box_[at(k)] = boxOf(path_[at(k)], std::min(end_[at(k)], regroupAt_[at(k)]) - t);
    for (int k : {a, b}) predictOwn(k, t);
    for (int k : {a, b}) predictPairs(k, t);
    return true;
}

void Simulator::airRelease(int i, double t, int keep, int keep2)
{
    if (airEdge_[at(i)] >= 0) {  // held on a nose edge: only the ball itself goes on freely
        airEdgeLetGo_[at(i)] = t;
        airEdgeLetGoOf_[at(i)] = airEdge_[at(i)];
        airEdge_[at(i)] = -1;
        regroupAt_[at(i)] = kNever;
        if (i != keep && i != keep2) {
            beginSegment(i, t, stateNow(i, t));
            r_.timelines[at(i)].back().held = true;
            predictOwn(i, t);
            predictPairs(i, t);
        }
        return;
    }
    const int other = airHeld_[at(i)];
    if (other < 0) return;
    airHeld_[at(i)] = -1;
    airHeld_[at(other)] = -1;
    airLetGo_[at(i)] = airLetGo_[at(other)] = t;
    airLetGoOf_[at(i)] = other;
    airLetGoOf_[at(other)] = i;
    for (int k : {i, other}) {
        regroupAt_[at(k)] = kNever;
        if (k == keep || k == keep2) continue;
        const bool pushed = heldFlight(k) || !push_[at(k)].isZero(0.0);
        // The ball on the cloth goes on as the hold judged it: a slip of rounding rolled out
        // (airHold). Left sliding, its friction (a few um/s of slip, ending within a microsecond)
        // would press it back on the flying ball that the hold just let go for want of that very
        // press: detection met the pair at once, the law (parting) and the hold (no force) left
        // it as it was, and it was met again at that instant until the event cap
        // (seed14-shot150029: a ball jumping off the cloth beside one whose slip had run out).
        BallState s = stateNow(k, t);
        const bool rolled = !flying(k) && rollOutRounding(s, radius(k), p_);
        if (pushed || rolled) {
            beginSegment(k, t, s);
            r_.timelines[at(k)].back().held = true;
        }
        predictOwn(k, t);
        predictPairs(k, t);
    }
}

void Simulator::heldFixedUntil(int a, double t, double limit)
{
    regroupAt_[at(a)] = t + std::max(limit, 1e-9);
    box_[at(a)] = boxOf(path_[at(a)], std::min(end_[at(a)], regroupAt_[at(a)]) - t);
    predictOwn(a, t);
    predictPairs(a, t);
}

bool Simulator::airEdgeHold(int a, int k, double t, const BallState& s)
{
    if (!flying(a) || series_[at(a)] || heldCount_[at(a)] > 0 || airHeld_[at(a)] >= 0 || !(s.z > 0.0)) return false;
    const CushionSegment& seg = table_.cushions[at(k)];
    const double R = radius(a), h = table_.cushionHeight, g = p_.gravity;
    // In the plane across the edge: nh along the cushion's normal (in front of the nose line), w up.
    const Vec2 along = seg.b - seg.a;
    const double L = along.norm();
    const double foot = (s.position - seg.a).dot(along) / L;
    const double nh = (s.position - seg.a).dot(seg.normal), w = (R + s.z) - h;
    const double dist = std::hypot(nh, w);
    if (!(foot >= 0.0 && foot <= L) || nh < 0.0 || w < 0.0 || !(dist > 0.0)) return false;
    const Vec3 N3(seg.normal.x(), seg.normal.y(), 0.0);
    const Vec3 n = (nh / dist) * N3 + Vec3(0.0, 0.0, w / dist);
    const Vec3 v = velocity3(s);
    const double vn = v.dot(n);
    const double across = v.dot(N3) * (w / dist) - s.vz * (nh / dist);  // the speed around the edge
    const double force = mass(a) * (g * n.z() - kHeldCurvatureShare * across * across / dist);
    if (!(force > 0.0) || std::abs(dist - R) > kHeldGap || std::abs(vn) > kHoldSpeed) return false;
    BallState st = s;
    if (vn != 0.0) {  // re-seated (as in airHold): the fixed edge takes the impulse
        st.velocity -= vn * seg.normal * (nh / dist);
        st.vz -= vn * (w / dist);
    }
    airEdge_[at(a)] = k;
    const Vec3 push = (force / mass(a)) * n;
    beginHeldFlight(a, t, st, push);
    // The segment: the normal turns about the edge (CircleLimits in the plane across it), and the
    // foot stays on the segment.
    const SpacePath pa = spaceNow(a, t);
    const Vec3 e(along.x() / L, along.y() / L, 0.0);  // along the edge
    auto acrossOf = [&](const Vec3& x) { return Vec3(x - x.dot(e) * e); };
    const Vec3 edge0(seg.a.x(), seg.a.y(), h);
    const CircleLimits l = circleLimits<Vec3>(acrossOf(edge0 - pa.c0), acrossOf(-pa.c1), acrossOf(-pa.c2), R);
    double limit = std::min({kMaxHeldSegment, l.gap, l.drop});
    const Vec2 tHat = along / L;
    const double f0 = (pa.c0.head<2>() - seg.a).dot(tHat), f1 = pa.c1.head<2>().dot(tHat), f2 = pa.c2.head<2>().dot(tHat);
    limit = std::min({limit, firstCrossing(f0, f1, f2, 0.0), firstCrossing(f0, f1, f2, L)});
    heldFixedUntil(a, t, limit);
    return true;
}

bool Simulator::airEdgeGeometry(int a, const CushionSegment& seg, const BallState& s, ContactLink& link, double& gap,
                                double& vn) const
{
    // The nose edge is the segment at the nose height, its ends the slab's top corners
    // (CushionContactKind::End's): the contact is with its nearest point.
    const double R = radius(a), h = table_.cushionHeight;
    const Vec2 along = seg.b - seg.a;
    const double L = along.norm();
    const Vec2 tHat = along / L;
    const double foot = (s.position - seg.a).dot(tHat);
    const double nh = (s.position - seg.a).dot(seg.normal), w = (R + s.z) - h;
    const Vec2 nearest = seg.a + std::clamp(foot, 0.0, L) * tHat;
    const Vec3 rel(s.position.x() - nearest.x(), s.position.y() - nearest.y(), w);
    const double dist = rel.norm();
    if (nh < 0.0 || w < 0.0 || !(dist > 0.0)) return false;
    const Vec3 out = rel / dist;
    const Vec3 v = velocity3(s);
    link.normal = -out.head<2>();
    link.nz = -out.z();
    gap = dist - R;
    vn = v.dot(out);
    // The curvature of the motion about the edge (its speed along the edge excluded) or the corner.
    const bool onEdge = foot >= 0.0 && foot <= L;
    const double alongSpeed = onEdge ? v.head<2>().dot(tHat) : 0.0;
    link.curvature = std::max(0.0, v.squaredNorm() - vn * vn - alongSpeed * alongSpeed) / dist;
    return true;
}

// A flying ball held on a jaw's rim, the circle at the nose height (seed12-shot810097: bounces ever
// lower on it until a root at 6e-9 s was lost in the rim's polynomial and the ball sank 2.2 cm into
// the jaw), as on a nose edge above.
bool Simulator::airRimHold(int a, int k, double t, const BallState& s)
{
    if (!flying(a) || series_[at(a)] || heldCount_[at(a)] > 0 || airHeld_[at(a)] >= 0 || !(s.z > 0.0)) return false;
    const JawTip& jaw = table_.jaws[at(k)];
    const double R = radius(a), h = table_.cushionHeight, g = p_.gravity, rj = jaw.radius;
    // In the plane through the jaw's axis and the centre: nh out from the rim (horizontally), w up.
    const Vec2 rel = s.position - jaw.centre;
    const double rho = rel.norm();
    if (!(rho > rj) || !onJawArc(jaw, s.position, kContactTolerance)) return false;
    const Vec2 u = rel / rho;
    const double nh = rho - rj, w = (R + s.z) - h;
    const double dist = std::hypot(nh, w);
    if (w < 0.0 || !(dist > 0.0)) return false;
    const Vec3 n = (nh / dist) * Vec3(u.x(), u.y(), 0.0) + Vec3(0.0, 0.0, w / dist);
    const Vec3 v = velocity3(s);
    const double vn = v.dot(n);
    // The centre keeps its distance from the rim on a torus: across the rim its curvature is 1/dist,
    // along it (nh/dist)/rho; the force takes kHeldCurvatureShare of the normal acceleration the
    // motion along the torus needs.
    const Vec3 alongRim(-u.y(), u.x(), 0.0);
    const double vAlong = v.dot(alongRim);
    const Vec3 vAcross = v - vn * n - vAlong * alongRim;
    const double curvature = vAcross.squaredNorm() / dist + vAlong * vAlong * (nh / dist) / rho;
    const double force = mass(a) * (g * n.z() - kHeldCurvatureShare * curvature);
    if (!(force > 0.0) || std::abs(dist - R) > kHeldGap || std::abs(vn) > kHoldSpeed) return false;
    BallState st = s;
    if (vn != 0.0) {  // re-seated (as in airEdgeHold): the fixed rim takes the impulse
        st.velocity -= vn * n.head<2>();
        st.vz -= vn * n.z();
    }
    airEdge_[at(a)] = static_cast<int>(table_.cushions.size()) + k;
    beginHeldFlight(a, t, st, (force / mass(a)) * n);
    // The segment: the frozen normal turns about the rim point (CircleLimits: the distance from that
    // point bounds the distance from the rim), and the centre stays over the tip's arc.
    const SpacePath pa = spaceNow(a, t);
    const Vec3 rim(jaw.centre.x() + rj * u.x(), jaw.centre.y() + rj * u.y(), h);
    const CircleLimits l = circleLimits<Vec3>(rim - pa.c0, -pa.c1, -pa.c2, R);
    double limit = std::min({kMaxHeldSegment, l.gap, l.drop});
    for (const Vec2& run : jaw.runs) {
        if (run.isZero(0.0)) continue;
        const double f0 = (pa.c0.head<2>() - jaw.centre).dot(run), f1 = pa.c1.head<2>().dot(run), f2 = pa.c2.head<2>().dot(run);
        limit = std::min(limit, firstCrossing(f0, f1, f2, 0.0));
    }
    heldFixedUntil(a, t, limit);
    return true;
}

bool Simulator::airHoldRule(Event& e, const AirBallBallResult& res)
{
    // Contact.h's hold rule for a flying ball a that comes down on a ball b on the cloth: when the
    // law leaves them parting slower than kHoldSpeed, with b's hop off the cloth within kHeldGap
    // (the cloth's answer to the law's push into it: its rebound is the cloth's restitution of a
    // rounding), the pair is pressed (a's weight) and would meet again and again, each time a
    // little slower, b bouncing on the cloth in between: a Zeno run of impacts to the event cap
    // (seed14-shot161368: a ball come to rest on top of a rolling ball). The micro-bounce is dropped
    // instead, as on the cloth: b's hop goes into the cloth (as a landing's, only energy is lost),
    // and the air hold takes the pair (its re-seat takes the parting away, an inelastic impulse along
    // the normal); if the forces do not press it, the law's result stands.
    const int i = e.balls[0], j = e.balls[1];
    const int ka = res.a.z >= res.b.z ? 0 : 1;  // a: the higher ball
    const int a = ka == 0 ? i : j, b = ka == 0 ? j : i;
    const BallState& beforeB = e.before[1 - ka];
    BallState sa = ka == 0 ? res.a : res.b;
    BallState sb = ka == 0 ? res.b : res.a;
    // (a is in the air, its weight pressing it on b: a ball leaving the cloth beside b, z = 0, is
    // pressed only by b's cloth friction, and held it was let go and met again at once until the
    // event cap, seed17-shot562088, 564948.)
    if (sa.motion != MotionState::Airborne || !(sa.z > 0.0) || beforeB.z != 0.0 || sb.z != 0.0 ||
        apexHeight(sb, p_.gravity) > kHeldGap)
        return false;
    sb.z = 0.0;
    sb.vz = 0.0;
    sb.motion = classify(sb, radius(b));
    // (n from b's centre to a's: > 0 parting)
    const Vec3 n = ka == 0 ? Vec3(-res.normal) : res.normal;
    const double separation = (velocity3(sa) - velocity3(sb)).dot(n);
    if (!(separation < kHoldSpeed)) return false;
    const std::size_t index = r_.events.size();
    e.after[ka] = sa;
    e.after[1 - ka] = sb;
    const Vec2 flat = res.normal.head<2>();
    e.normal = flat.norm() > 0.0 ? Vec2(flat.normalized()) : Vec2(Vec2::Zero());
    e.contactPoint = e.before[0].position + radius(i) * flat;
    e.approachSpeed = res.approachSpeed;
    e.impulse = res.impulse;
    // A pair that a group touches (b held by the cloth with a third body, or a held on one): the
    // contact is a row in space of that group (settle), solved with the group's other rows; a
    // pairwise hold would hand a back and forth with the group (seed16-shot68467, 585155).
    // So too a flying ball that another ball's hold let go at this instant: wedged between the two, it
    // would be handed back and forth by pairwise holds (seed16-shot260322), as in the wedge rule above.
    // And the ball on the cloth, let go at this instant by a second flying ball (wide-seed16-shot100384:
    // a sliding ball between two balls coming down on it, the two pairwise holds taking turns at one
    // instant, each approach 0.6 of the last, to the event cap).
    const bool wedged = (airLetGo_[at(a)] == e.time && airLetGoOf_[at(a)] != b) ||
                        (airLetGo_[at(b)] == e.time && airLetGoOf_[at(b)] != a);
    if (wedged || heldCount_[at(a)] > 0 || heldCount_[at(b)] > 0) {
        if (holdCollision(e, HeldContact{i, ContactBody::Ball, j}, separation)) return true;
        e.held = false;
        return false;
    }
    e.held = true;
    r_.events.push_back(e);
    if (airHold(a, b, e.time, sa, sb, true)) {
        r_.events[index].after[0] = state_[at(i)];
        r_.events[index].after[1] = state_[at(j)];
        return true;
    }
    r_.events.pop_back();
    e.held = false;
    return false;
}

}  // namespace cuelab::detail
