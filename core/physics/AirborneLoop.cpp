// Airborne balls in the event loop (issue 23; docs/airborne.md, "Wired into the event loop"): the
// elevated strike, flights, landings and bounce series, and the prediction of a flying ball's
// contacts with cushions, jaws, pockets and other balls (their collisions: AirCollisions.cpp).
// Nothing here runs for a ball that never leaves the cloth, so every setup without an elevated
// strike or a height gives the events it gave before.

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
    // Leaving the table's outline over a pocket's mouth (beyond the pocket, over the rail's top or
    // the floor): `ball-off-table` there, as over a straight rail at its nose line (issue 40; index -1).
    if (!heldFlight(i)) {
        const double exit = outlineExitTime(sp, R, table_, horizon);
        const Candidate cand{now + exit, 1, i, Agent::Cushion, -1};
        if (exit != kNever && earlier(cand, best)) best = cand;
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

}  // namespace cuelab::detail
