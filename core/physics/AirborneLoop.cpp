// Airborne balls in the event loop (issue 23; docs/airborne.md, "Wired into the event loop"): the
// elevated strike, flights, landings and bounce series, and a flying ball's contacts with cushions,
// jaws, pockets and other balls. Nothing here runs for a ball that never leaves the cloth, so every
// setup without an elevated strike or a height gives the events it gave before.

#include "Simulator.h"

#include "AirImpacts.h"
#include "ElevatedStrike.h"

#include <algorithm>
#include <cmath>

namespace cuelab::detail {

namespace {

// m: slack of the conservative tests that decide whether a bounce series can be summed.
constexpr double kSeriesSlack = 1e-9;

// The number of bounces in a row taken as single events after which a series whose rest is below
// kSeriesNegligible (reach and height) is summed whatever lies near it: with e = 0.5 its rebounds are
// then 2^-64 of the first, far below any distance the loop resolves.
constexpr int kBounceCap = 64;
constexpr double kSeriesNegligible = 1e-12;

bool boxesWithin(const Box& a, const Box& b, double distance)
{
    return a.lo.x() - distance <= b.hi.x() && b.lo.x() - distance <= a.hi.x() && a.lo.y() - distance <= b.hi.y()
           && b.lo.y() - distance <= a.hi.y();
}

// Whether the box comes within `reach` of a cushion's slab: the region behind its nose line (and up
// to reach in front of it) over the segment's length (and reach past its ends). A flying ball can
// meet the slab anywhere behind the line (its top, its ends: airCushionContact), not only near the
// segment itself. n and the position along the segment are linear: their ranges over the box are
// those over its corners.
bool boxNearSlab(const Box& box, double reach, const CushionSegment& seg)
{
    const Vec2 along = seg.b - seg.a;
    const double length = along.norm();
    const Vec2 t = along / length;
    double nLow = kNever, tLow = kNever, tHigh = -kNever;
    for (const Vec2& c : {box.lo, box.hi, Vec2(box.lo.x(), box.hi.y()), Vec2(box.hi.x(), box.lo.y())}) {
        nLow = std::min(nLow, (c - seg.a).dot(seg.normal));
        tLow = std::min(tLow, (c - seg.a).dot(t));
        tHigh = std::max(tHigh, (c - seg.a).dot(t));
    }
    const double r = reach + kSeriesSlack;
    return nLow <= r && tLow <= length + r && tHigh >= -r;
}

}  // namespace

void Simulator::strike(int i, const CueStrike& shot)
{
    ElevatedStrikeResult es = resolveElevatedStrike(state_[at(i)], radius(i), mass(i), shot, p_);
    if (!strikeKeepsElevation_) es.bounced = false;  // the level strike of before (SimulationOptions)
    const CueImpactResult& cue = es.cue;
    Event e;
    e.kind = EventKind::CueStrike;
    e.time = 0.0;
    e.balls[0] = i;
    e.before[0] = state_[at(i)];
    // A level strike is CueImpact's, on the cloth, bit for bit; an elevated one keeps its vertical
    // part, into the cloth, which answers at once (the `ball-table` event at t = 0).
    e.after[0] = es.bounced ? lifted(cue.after, 0.0, es.vzIntoCloth) : cue.after;
    e.contactPoint = cue.contactPoint;
    e.normal = cue.heading;
    e.approachSpeed = shot.speed;
    e.impulse = cue.impulse;
    r_.events.push_back(e);
    if (!es.bounced) {
        beginSegment(i, 0.0, cue.after);
        return;
    }
    Event b;
    b.kind = EventKind::BallTable;
    b.time = 0.0;
    b.balls[0] = i;
    b.before[0] = e.after[0];
    b.after[0] = es.after;
    b.after[0].motion = classify(b.after[0], radius(i));
    b.contactPoint = b.before[0].position;
    b.approachSpeed = es.bounce.approachSpeed;
    b.impulse = es.bounce.impulse;
    r_.events.push_back(b);
    // The first flight is always taken as a flight: the others are not predicted yet, so whether its
    // series could be summed is decided at its landing.
    beginSegment(i, 0.0, es.after);
}

void Simulator::predictAirContacts(int i, double now, const Path& p, Candidate& best)
{
    const double R = radius(i);
    const BallState s = stateNow(i, now);
    const SpacePath sp = spaceNow(i, now);
    const double landing = end_[at(i)];
    const Box& box = box_[at(i)];
    // It drops into a pocket when its centre comes down to the cloth's level over the pocket's
    // circle (there is no cloth there): at its landing, instead of a bounce. A ball over a pocket
    // higher up flies over it.
    // (Only in place of the landing itself: a held flight's refresh before it stays the ball's own
    // next event.)
    if (landing != kNever && landing <= best.time) {
        const Vec2 down = heldFlight(i) ? Vec2(sp.at(landing - now).head<2>()) : Vec2(s.position + (landing - now) * s.velocity);
        for (std::size_t k = 0; k < table_.pockets.size(); ++k) {
            const Pocket& pk = table_.pockets[k];
            if ((down - pk.centre).squaredNorm() <= pk.radius * pk.radius) {
                best = Candidate{landing, 0, i, Agent::Pocket, static_cast<int>(k)};
                break;
            }
        }
    }
    const double horizon = landing - now;
    for (std::size_t k = 0; k < table_.cushions.size(); ++k) {
        if (!boxNearSlab(box, R, table_.cushions[k]) || airEdge_[at(i)] == static_cast<int>(k)) continue;  // (held on its edge)
        if (heldCount_[at(i)] > 0 && heldWall(i, ContactBody::Cushion, static_cast<int>(k))) continue;  // (a row of its group: a face or an edge)
        const AirCushionContact c = airCushionContact(sp, R, table_.cushions[k], table_.cushionHeight, horizon);
        if (c.kind == CushionContactKind::None || c.time == kNever) continue;
        const Candidate cand{now + c.time, 1, i, Agent::Cushion, static_cast<int>(k)};
        if (earlier(cand, best)) {
            best = cand;
            airContact_[at(i)] = c;
        }
    }
    for (std::size_t k = 0; k < table_.jaws.size(); ++k) {
        const JawTip& jaw = table_.jaws[k];
        if (!boxNearCircle(box, R + jaw.radius, jaw.centre) || airEdge_[at(i)] == static_cast<int>(table_.cushions.size() + k)) continue;  // (held on its rim)
        if (heldCount_[at(i)] > 0 && heldWall(i, ContactBody::Jaw, static_cast<int>(k))) continue;  // (its side a row of its group)
        // Its side, its top or its rim (airJawContact).
        const AirCushionContact c = airJawContact(sp, R, jaw, table_.cushionHeight, horizon);
        if (c.kind == CushionContactKind::None || c.time == kNever) continue;
        const Candidate cand{now + c.time, 1, i, Agent::Jaw, static_cast<int>(k)};
        if (earlier(cand, best)) {
            best = cand;
            airContact_[at(i)] = c;
        }
    }
    (void)p;
}

bool Simulator::riding(int a, int b) const
{
    return airRide_[at(a)] == b && airRideSegments_[at(a)] == r_.timelines[at(a)].size() &&
           airRidePartnerSegments_[at(a)] == r_.timelines[at(b)].size();
}

double Simulator::airPairTime(int i, int j, double now) const
{
    const double ri = radius(i), rj = radius(j);
    // In space the balls touch at Ra + Rb (on the cloth the horizontal touchDistance is smaller for
    // unequal radii), so the boxes are compared at that distance.
    if (!boxesWithin(window_[at(i)], window_[at(j)], ri + rj + kSeriesSlack)) return kNever;
    const double horizon = std::min(horizon_[at(i)], horizon_[at(j)]) - now;
    if (horizon < 0.0) return kNever;
    if (riding(i, j) || riding(j, i)) return kNever;
    const double s = spaceBallBallTime(spaceNow(i, now), ri, spaceNow(j, now), rj, horizon);
    return s == kNever ? kNever : now + s;
}

Box Simulator::seriesBox(const SeriesTail& tail) const
{
    Box b;
    b.lo = tail.from.array() - tail.reach;
    b.hi = tail.from.array() + tail.reach;
    return b;
}

bool Simulator::seriesClear(int i, const SeriesTail& tail, double end, int j, double now) const
{
    // Ball i stays within `reach` of `from` horizontally and below tail.maxHeight until `end`. Ball j
    // stays within its own series' disc, or within (|v| + 2/7 |u| + |push| d) d of where it is now
    // (d = end - now) until its next event: no ball on the cloth or in flight gets faster than that
    // without one, and its next event predicts its pairs again, from its side. A flying j is above
    // the lower end of its parabola over that time (it is concave), which lets a ball bounce under
    // one that rises away from it.
    Vec2 centre;
    double reach;
    double low = 0.0;  // the least height z of j until its next event or `end`
    if (series_[at(j)]) {
        const SeriesTail other = seriesTail(seriesOf_[at(j)], 1);
        centre = other.from;
        reach = other.reach;
    } else {
        const BallState s = stateNow(j, now);
        const double d = std::max(0.0, end - now);
        centre = s.position;
        reach = (s.velocity.norm() + (2.0 / 7.0) * slipVelocity(s, radius(j)).norm() + push_[at(j)].norm() * d) * d;
        if (flying(j)) {
            const double until = std::min(d, end_[at(j)] - now);
            low = std::max(0.0, std::min(s.z, fly(s, p_.gravity, std::max(0.0, until)).z));
        }
    }
    const double across = std::max(0.0, (centre - tail.from).norm() - tail.reach - reach);
    const double up = std::max(0.0, (radius(j) + low) - (radius(i) + tail.maxHeight));
    const double touch = radius(i) + radius(j) + kSeriesSlack;
    return across * across + up * up > touch * touch;
}

double Simulator::seriesPairTime(int i, int j, double now) const
{
    auto summedAnyway = [&](int b) {
        if (!series_[at(b)] || bounces_[at(b)] < kBounceCap) return false;
        const SeriesTail tail = seriesTail(seriesOf_[at(b)], 1);
        return tail.reach + tail.maxHeight <= kSeriesNegligible;
    };
    if (summedAnyway(i) || summedAnyway(j)) return kNever;
    const int a = series_[at(i)] ? i : j;
    const int b = a == i ? j : i;
    if (seriesClear(a, seriesTail(seriesOf_[at(a)], 1), end_[at(a)], b, now)) return kNever;
    return now;
}

bool Simulator::seriesIsolated(int i, const BounceSeries& b, double now) const
{
    if (b.duration == kNever) return false;
    const SeriesTail tail = seriesTail(b, 1);
    if (bounces_[at(i)] >= kBounceCap && tail.reach + tail.maxHeight <= kSeriesNegligible) return true;
    const double R = radius(i);
    const Box box = seriesBox(tail);
    for (const CushionSegment& seg : table_.cushions)
        if (boxNearSegment(box, R + kSeriesSlack, seg)) return false;
    for (const JawTip& jaw : table_.jaws)
        if (boxNearCircle(box, R + jaw.radius + kSeriesSlack, jaw.centre)) return false;
    for (const Pocket& pk : table_.pockets)
        if (boxNearCircle(box, pk.radius + kSeriesSlack, pk.centre)) return false;
    for (int j = 0; j < n_; ++j) {
        if (j == i || isOutOfPlay(state_[at(j)].motion)) continue;
        if (!seriesClear(i, tail, now + b.duration, j, now)) return false;
    }
    return true;
}

void Simulator::beginSeries(int i, double t, const BallState& landing, const BounceSeries& b)
{
    BallState st = landing;
    st.motion = MotionState::Airborne;  // (its numbers say "on the cloth, coming down": the series' start)
    start_[at(i)] = t;
    state_[at(i)] = st;
    push_[at(i)] = Vec2::Zero();
    series_[at(i)] = 1;
    seriesOf_[at(i)] = b;
    path_[at(i)] = Path{landing.position, Vec2::Zero(), Vec2::Zero()};
    end_[at(i)] = t + b.duration;
    box_[at(i)] = seriesBox(seriesTail(b, 1));
    MotionSegment seg{t, st, Vec2::Zero(), false};
    seg.bounces = true;
    r_.timelines[at(i)].push_back(seg);
}

bool Simulator::overCloth(const Vec2& c) const
{
    if (c.x() >= 0.0 && c.x() <= table_.length && c.y() >= 0.0 && c.y() <= table_.width) return true;
    // Beyond a nose line: still over the cloth of a pocket's mouth near the pocket, on the table's side
    // of the pocket (its centre no farther from the playing area than the pocket's centre; past the
    // pocket there is no cloth).
    for (const Pocket& pk : table_.pockets) {
        if ((c - pk.centre).norm() > pk.radius + table_.ballRadius) continue;
        const Vec2 nearest(std::clamp(pk.centre.x(), 0.0, table_.length), std::clamp(pk.centre.y(), 0.0, table_.width));
        if ((c - pk.centre).dot(nearest - pk.centre) >= 0.0) return true;
    }
    return false;
}

void Simulator::land(int i, double t)
{
    const double R = radius(i), m = mass(i);
    BallState landing = stateNow(i, t);  // (evolve holds a flight at its landing, z = 0)
    landing.z = 0.0;
    // Down at the flight's landing speed, sqrt(vz0^2 + 2 g z0) from its start (exactly -vz0 from the
    // cloth): a flight shorter than the clock's resolution at t (a tiny rebound) lands at t itself,
    // where evolve has not turned it down yet.
    // (A held flight comes down under g less its push's vertical part.)
    landing.vz = -landingSpeed(state_[at(i)], p_.gravity - pushZ_[at(i)]);
    landing.motion = MotionState::Airborne;
    Event e;
    e.kind = EventKind::BallTable;
    e.time = t;
    e.balls[0] = i;
    e.before[0] = landing;
    e.contactPoint = landing.position;
    e.approachSpeed = -landing.vz;
    if (!overCloth(landing.position)) {
        // It came down beyond the cushions (over a rail's end or a jaw, whose tops are not modelled as
        // surfaces): there is no cloth there, so it has left the table.
        e.kind = EventKind::BallOffTable;
        e.after[0] = BallState{};
        e.after[0].position = landing.position;
        e.after[0].motion = MotionState::OffTable;
        e.approachSpeed = 0.0;
        bounces_[at(i)] = 0;
        finishEvent(t, e);
        return;
    }
    ++bounces_[at(i)];
    const BounceSeries b = bounceSeriesOf(landing, R, p_);
    // The whole rest of the series in one segment when nothing can meet the ball before it ends;
    // otherwise this bounce alone, and the next landing decides again (each bounce shrinks the rest).
    const BallState one = resolveTableImpact(landing, R, m, p_).after;
    // A rebound whose flight would last less than a picosecond is below the clock's resolution: the
    // ball lands for good at the series' end now, as a flight's continuation does (Motion.cpp's
    // applyTransition, which the results' states past a segment's end follow).
    const bool settles = 2.0 * one.vz < 1e-12 * p_.gravity && b.duration != kNever;
    // (A ball held on a group of the cloth lands alone, and its group is solved again with it.)
    const bool inGroup = heldCount_[at(i)] > 0;
    const bool whole = !inGroup && !settles && b.duration > 0.0 && b.duration != kNever && seriesIsolated(i, b, t);
    e.after[0] = settles ? b.end : whole ? seriesStateAt(b, 0.0) : one;
    e.after[0].motion = classify(e.after[0], R);
    e.impulse = m * (velocity3(e.after[0]) - velocity3(landing));
    if (inGroup) {
        if (e.after[0].motion != MotionState::Airborne) bounces_[at(i)] = 0;
        finishEvent(t, e);
        return;
    }
    r_.events.push_back(e);
    if (whole) {
        beginSeries(i, t, landing, b);
    } else {
        if (e.after[0].motion != MotionState::Airborne) bounces_[at(i)] = 0;
        beginSegment(i, t, e.after[0]);
    }
    predictOwn(i, t);
    predictPairs(i, t);
}

void Simulator::endSeries(int i, double t)
{
    const BounceSeries& b = seriesOf_[at(i)];
    Event e;
    e.kind = EventKind::BallTable;
    e.time = t;
    e.balls[0] = i;
    // The limit of infinitely many bounces: it arrives with z = vz = 0, so the event changes no
    // number; it marks where and when the ball is on the cloth for good.
    e.before[0] = b.end;
    e.before[0].motion = MotionState::Airborne;
    e.after[0] = b.end;
    e.after[0].motion = classify(b.end, radius(i));
    e.contactPoint = b.end.position;
    bounces_[at(i)] = 0;
    finishEvent(t, e);
}

void Simulator::splitSeries(int i, double t)
{
    const BallState s = stateNow(i, t);
    bounces_[at(i)] = 0;
    beginSegment(i, t, s);
    predictOwn(i, t);
    predictPairs(i, t);
}

void Simulator::airCushion(const Candidate& c, Event& e)
{
    const int i = c.ball;
    const double R = radius(i);
    const BallState& before = e.before[0];
    Vec3 normal;  // from the body towards the centre
    if (c.agent == Agent::Cushion) {
        const CushionSegment& seg = table_.cushions[at(c.index)];
        const AirCushionContact& contact = airContact_[at(i)];
        e.cushion = c.index;
        if (contact.kind == CushionContactKind::OffTable) {
            // Over a pocket's circle with its bottom below the rail's top it met the rail's end (or
            // top) inside the pocket: it drops in. (Higher up it clears the rail, as below.)
            for (std::size_t k = 0; k < table_.pockets.size() && before.z < table_.cushionHeight; ++k) {
                const Pocket& pk = table_.pockets[k];
                if ((before.position - pk.centre).squaredNorm() > pk.radius * pk.radius) continue;
                e.kind = EventKind::BallPocket;
                e.cushion = -1;
                e.pocket = static_cast<int>(k);
                e.after[0] = BallState{};
                e.after[0].position = pk.centre;
                e.after[0].motion = MotionState::Pocketed;
                e.after[0].pocket = static_cast<int>(k);
                e.contactPoint = before.position;
                finishEvent(e.time, e);
                return;
            }
            // It clears the rail: out of play where it crossed the nose line, like a pocketed ball.
            e.kind = EventKind::BallOffTable;
            e.after[0] = BallState{};
            e.after[0].position = before.position;
            e.after[0].z = before.z;
            e.after[0].motion = MotionState::OffTable;
            e.contactPoint = before.position;
            e.normal = -seg.normal;
            finishEvent(e.time, e);
            return;
        }
        e.kind = EventKind::BallCushion;
        normal = contact.kind == CushionContactKind::Nose || contact.kind == CushionContactKind::End
                     ? contact.normal
                     : Vec3(seg.normal.x(), seg.normal.y(), 0.0);
    } else {
        // Its side, top or rim, along the normal its prediction found.
        e.kind = EventKind::BallJaw;
        e.jaw = c.index;
        normal = airContact_[at(i)].normal;
    }
    // A flying ball meets the cushion along the 3-D normal (a nose edge's is tilted up), with the
    // cushion's restitution and friction (AirImpacts.h). The cushion models of the cloth assume a ball
    // on the cloth, so they are not used here.
    const FixedImpactResult res = resolveFixedImpact(before, R, mass(i), normal, p_.cushionRestitution, p_.cushionFriction);
    e.after[0] = res.after;
    e.after[0].motion = classify(e.after[0], R);
    // A flying ball that a held group presses on a cushion's face, or that a ball's hold in the air
    // let go at this instant (its push pressed it there): the face would answer each press alone, the
    // group (or the other ball, met again at once) press it back, and the two hand it back and forth
    // at this instant until the event cap. The face is held as a row of the ball's group instead (a
    // horizontal normal, HeldContacts.cpp), solved with its other contacts, when the law leaves it
    // parting slower than kHoldSpeed (Contact.h's hold rule).
    // The same for a jaw's side (its vertical cylinder below the nose; seed21-shot106191).
    if (airContact_[at(i)].kind == CushionContactKind::Face && e.after[0].motion == MotionState::Airborne &&
        (heldCount_[at(i)] > 0 || airLetGo_[at(i)] == e.time) && normal.head<2>().norm() > 0.0) {
        const Vec2 out = c.agent == Agent::Cushion ? table_.cushions[at(c.index)].normal : Vec2(normal.head<2>().normalized());
        const double separation = e.after[0].velocity.dot(out);
        if (separation < kHoldSpeed) {
            e.normal = -out;
            e.contactPoint = before.position - R * out;
            e.approachSpeed = res.approachSpeed;
            e.impulse = res.impulse;
            const ContactBody body = c.agent == Agent::Cushion ? ContactBody::Cushion : ContactBody::Jaw;
            if (holdCollision(e, HeldContact{i, body, c.index}, separation)) return;
        }
    }
    // A bounce on a nose edge that leaves the ball parting slower than kHoldSpeed while gravity
    // presses it on: it would bounce ever lower (a Zeno run of impacts that the clock cannot resolve).
    // The edge holds it instead (AirHold.cpp), the rebound taken away (which only removes energy), as
    // the cloth's hold rule does for a collision on the cloth.
    // The same on a jaw's rim (its top is flat: a ball on it is not held).
    const bool rim = c.agent == Agent::Jaw && normal.head<2>().norm() > 0.0;
    // (A segment's bare end: its top corner, the nose edge's end, is held as the edge is, in a group.)
    const bool topCorner = c.agent == Agent::Cushion && airContact_[at(i)].kind == CushionContactKind::End && normal.z() > 0.0;
    if ((((rim || c.agent == Agent::Cushion) && airContact_[at(i)].kind == CushionContactKind::Nose) || topCorner) &&
        e.after[0].motion == MotionState::Airborne) {
        const double separation = Vec3(e.after[0].velocity.x(), e.after[0].velocity.y(), e.after[0].vz).dot(normal);
        // (A jaw's rim too: seed16-shot363458, a flying ball on a rim and a hopping ball, the rim's
        // hold and the ball handing it back and forth.)
        const int edgeId = c.agent == Agent::Cushion ? c.index : static_cast<int>(table_.cushions.size()) + c.index;
        if (separation < kHoldSpeed &&
            (topCorner || heldCount_[at(i)] > 0 || airLetGo_[at(i)] == e.time ||
             (airEdgeLetGo_[at(i)] == e.time && airEdgeLetGoOf_[at(i)] != edgeId))) {
            // Held in a group (on a ball, or on another edge), or let go at this instant by a hold on
            // another body that presses it on this edge too: it is wedged between the two, and pairwise
            // holds would hand it back and forth (seed12-shot988364: two nose edges in a corner;
            // seed14-shot652328: a ball on the cloth and a nose edge), each time a little into the
            // other, until a root was lost and the ball sank through the nose. The edge becomes a row
            // in space of a group (HeldContacts.cpp, airEdgeGeometry); the other contact, met at once,
            // joins it (groupHoldable, or this branch), and the rows are solved together.
            const Vec2 flat = normal.head<2>();
            e.normal = flat.norm() > 0.0 ? Vec2(-flat.normalized()) : Vec2(Vec2::Zero());
            e.contactPoint = before.position - R * flat;
            e.approachSpeed = res.approachSpeed;
            e.impulse = res.impulse;
            const ContactBody body = c.agent == Agent::Cushion ? ContactBody::Cushion : ContactBody::Jaw;
            if (holdCollision(e, HeldContact{i, body, c.index}, std::max(0.0, separation))) return;
        }
        if (separation < kHoldSpeed && !topCorner) {
            BallState seated = e.after[0];
            if (separation > 0.0) {
                seated.velocity -= separation * normal.head<2>();
                seated.vz -= separation * normal.z();
            }
            const std::size_t index = r_.events.size();
            Event held = e;
            held.after[0] = seated;
            held.held = true;
            const Vec2 flat = normal.head<2>();
            held.normal = flat.norm() > 0.0 ? Vec2(-flat.normalized()) : Vec2(Vec2::Zero());
            held.contactPoint = before.position - R * flat;
            held.approachSpeed = res.approachSpeed;
            held.impulse = res.impulse - mass(i) * std::max(0.0, separation) * normal;
            r_.events.push_back(held);
            if (c.agent == Agent::Cushion ? airEdgeHold(i, c.index, e.time, seated) : airRimHold(i, c.index, e.time, seated)) {
                r_.events[index].after[0] = state_[at(i)];
                return;
            }
            r_.events.pop_back();
        }
    }
    const Vec2 flat = normal.head<2>();
    e.normal = flat.norm() > 0.0 ? Vec2(-flat.normalized()) : Vec2(Vec2::Zero());
    e.contactPoint = before.position - R * flat;
    e.approachSpeed = res.approachSpeed;
    e.impulse = res.impulse;
    finishEvent(e.time, e);
}

void Simulator::airBallBall(const Candidate& c, Event& e)
{
    const int i = c.ball, j = c.index;
    e.kind = EventKind::BallBall;
    e.balls[1] = j;
    e.before[1] = stateNow(j, e.time);
    // The line of centres is tilted: both balls free in 3-D, and a ball on the cloth driven into it
    // answered by the cloth at once (AirImpacts.h).
    const AirBallBallResult res = resolveAirBallBall(e.before[0], radius(i), mass(i), e.before[1], radius(j), mass(j), p_);
    // Touching with no approach while gravity presses the flying ball on the other (a ball sliding
    // down a ball's side): the law gives no impulse and the same contact would be met again at this
    // instant, for ever. The pair is held instead (AirHold.cpp): the event marks where the hold
    // begins and changes no velocity.
    // So is an approach within kRestingSpeed whose impulse is lost in rounding: the law changes no
    // velocity (seed21-shot5186: a ball on the cloth whose friction presses it on a ball rising off
    // the cloth beside it, approaching at 8e-20 m/s, the law's 1e-20 N s lost, met again at that
    // instant until the event cap). (A law that does change them stands: seed19-shot723846's
    // 4e-12 m/s joins the group its balls are held in, as a collision.)
    auto unchanged = [](const BallState& x, const BallState& y) {
        return x.velocity == y.velocity && x.vz == y.vz && x.spin == y.spin;
    };
    const bool resting = res.approachSpeed <= kRestingSpeed &&
                         (res.impulse.isZero(0.0) || (unchanged(res.a, e.before[0]) && unchanged(res.b, e.before[1])));
    if (resting) {
        const int a = flying(i) ? i : j, b = a == i ? j : i;
        // A held event marks where the hold begins and changes no velocity (the fall-through below
        // sets every one of these fields again for the law's result).
        e.after[0] = e.before[0];
        e.after[1] = e.before[1];
        e.normal = res.normal.head<2>().norm() > 0.0 ? Vec2(res.normal.head<2>().normalized()) : Vec2(Vec2::Zero());
        e.contactPoint = e.before[0].position + radius(i) * res.normal.head<2>();
        e.approachSpeed = res.approachSpeed;
        e.impulse = Vec3::Zero();
        // A flying ball that another ball let go at this instant (this event's, Simulator.cpp's
        // process) and that is pressed on this one too is wedged between them: the pairwise air holds
        // would hand it back and forth at this instant until the event cap (seed12-shot655830: a
        // ball dropping between two rolling balls). It is held with this contact as a row in space
        // of a group instead (HeldContacts.cpp); the other contact, met at once, joins that group
        // (groupHoldable), and the two rows are solved together.
        // The same for a flying b let go at this instant by its hold on a third ball that presses it
        // on a (seed21-shot102774, a break: three balls nearly in a line, the middle one 0.1 mm up,
        // held on the ball on the cloth and pressed by that hold on the third, itself in the air;
        // the air hold and this contact handed the middle ball back and forth at one instant).
        // And for either ball let go at this instant by a nose edge or a jaw's rim that presses it on
        // the other (seed16-shot363458: a flying ball on a rim and a hopping ball); the edge or rim,
        // met at once, joins the group (airCushion).
        const bool wedged = (airLetGo_[at(a)] == e.time && airLetGoOf_[at(a)] != b && !flying(b)) ||
                            (flying(b) && airLetGo_[at(b)] == e.time && airLetGoOf_[at(b)] != a) ||
                            airEdgeLetGo_[at(a)] == e.time || (flying(b) && airEdgeLetGo_[at(b)] == e.time);
        if (wedged && holdCollision(e, HeldContact{i, ContactBody::Ball, j}, 0.0)) return;
        if (!wedged && airHoldable(a, b)) {
            e.held = true;  // (with no hold impulse: a pressed pair may part by a few nm/s, Detection.h)
            const std::size_t index = r_.events.size();
            r_.events.push_back(e);
            if (airHold(a, b, e.time)) {
                r_.events[index].after[0] = state_[at(i)];
                r_.events[index].after[1] = state_[at(j)];
                return;
            }
            r_.events.pop_back();
            e.held = false;
        }
        if (!heldFlight(a) && apexHeight(e.before[a == i ? 0 : 1], p_.gravity) <= kHeldGap) {
            // Not held (b is held by the cloth in a group, or the air hold finds no force: the cloth's
            // friction presses b on a level a, seed11-shot4654's 9.4e-12 m hop), and a's hop
            // stays within kHeldGap of the cloth (a frictional law's vertical throw of a few
            // nanometres: seed7-shot190, 1.9e-9 m): the cloth takes the hop, as a landing does, and
            // the pair meets again on the cloth, where the group holds it. The event is that landing.
            // First, the hop rides out its flight to its own landing (no jump in height) when the
            // two paths, left unanswered, press no deeper than kContactTolerance into each other
            // until then or until either ball's next segment (seed15-shot244191: a ball thrown up
            // 4 nm beside a ball it nudges along at a few nm/s, whose rolling resistance brings it
            // back within nanoseconds). Nothing changes and there is no event: the pair is not met
            // again while the ride lasts (riding), and after it the paths are predicted again.
            const double rideEnd = std::min({end_[at(a)], end_[at(b)], horizon_[at(a)], horizon_[at(b)]}) - e.time;
            if (spaceBallBallWithin(spaceNow(a, e.time), radius(a), spaceNow(b, e.time), radius(b), kContactTolerance, rideEnd)) {
                airRide_[at(a)] = b;
                airRideSegments_[at(a)] = r_.timelines[at(a)].size();
                airRidePartnerSegments_[at(a)] = r_.timelines[at(b)].size();
                predictPairs(a, e.time);
                return;
            }
            const BallState before = e.before[a == i ? 0 : 1];
            Event land;
            land.kind = EventKind::BallTable;
            land.time = e.time;
            land.balls[0] = a;
            land.before[0] = before;
            land.after[0] = before;
            land.after[0].z = 0.0;
            land.after[0].vz = 0.0;
            land.after[0].motion = classify(land.after[0], radius(a));
            land.contactPoint = before.position;
            land.impulse = Vec3(0.0, 0.0, -mass(a) * before.vz);
            finishEvent(e.time, land);
            return;
        } else if (groupHoldable(a, b)) {
            // b is held by the cloth in a group (or a is held on one): a's contact joins that group as
            // a row in space (Contact.h's ContactLink::nz), held as the group's others are (its
            // re-seating may take away a rounding's approach).
            if (holdCollision(e, HeldContact{i, ContactBody::Ball, j}, 0.0)) return;
        }
    }
    if (!resting && airHoldRule(e, res)) return;
    e.after[0] = res.a;
    e.after[1] = res.b;
    if (resting) {
        // Touching with no approach and not held: the ball on the cloth goes on as the air hold
        // judged it, a slip of rounding rolled out (as airRelease's). Left sliding, its friction
        // would press it back at once on the flying ball the hold found no force for: met again at
        // this instant until the event cap (seed14-shot150029).
        // So too a ball rolling slower than kRollOffSpeed, which the hold takes as at rest: it
        // stops (its rolling resistance would end it within nanoseconds, a micrometre's billionth
        // on). Left rolling, that resistance pressed it on the flying ball until then, and the pair
        // was met again at this instant until the event cap (seed18-shot346856: 6e-10 m/s).
        for (std::size_t k = 0; k < 2; ++k) {
            if (e.before[k].motion == MotionState::Airborne) continue;
            BallState& s = e.after[k];
            rollOutRounding(s, radius(e.balls[k]), p_);
            if (classify(s, radius(e.balls[k])) == MotionState::Rolling && s.velocity.norm() <= kRollOffSpeed) {
                s.velocity = Vec2::Zero();
                s.spin.x() = 0.0;
                s.spin.y() = 0.0;
            }
        }
    }
    e.after[0].motion = classify(e.after[0], radius(i));
    e.after[1].motion = classify(e.after[1], radius(j));
    const Vec2 flat = res.normal.head<2>();
    e.normal = flat.norm() > 0.0 ? Vec2(flat.normalized()) : Vec2(Vec2::Zero());
    e.contactPoint = e.before[0].position + radius(i) * flat;
    e.approachSpeed = res.approachSpeed;
    e.impulse = res.impulse;
    finishEvent(e.time, e);
}

}  // namespace cuelab::detail
