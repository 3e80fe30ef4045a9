#include "Checks.h"

#include "BallBallCollision.h"
#include "Contact.h"
#include "BounceSeries.h"
#include "Flight.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace cuelab::testing {

namespace {

std::string number(double v)
{
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

}  // namespace

Ball ballAt(const Table& table, const std::string& id, const Vec2& position, const Vec2& velocity, const Vec3& spin)
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

// The signed distance d of (x, y) from the cushion's line, when its foot falls on the segment.
static bool distanceOverSegment(const CushionSegment& c, double x, double y, double& d)
{
    const double ax = c.a.x(), ay = c.a.y(), bx = c.b.x() - ax, by = c.b.y() - ay;
    const double lambda = ((x - ax) * bx + (y - ay) * by) / (bx * bx + by * by);
    if (lambda < 0.0 || lambda > 1.0) return false;
    d = (x - ax) * c.normal.x() + (y - ay) * c.normal.y();
    return true;
}

double cushionOverlap(const Table& t, double x, double y, double R)
{
    double worst = -1.0;
    for (const CushionSegment& c : t.cushions) {
        double d = 0.0;
        if (!distanceOverSegment(c, x, y, d)) continue;
        worst = std::max(worst, R - d);
    }
    for (const JawTip& j : t.jaws) {
        const double dx = x - j.centre.x(), dy = y - j.centre.y();
        worst = std::max(worst, R + j.radius - std::sqrt(dx * dx + dy * dy));
    }
    return worst;
}

double cushionOverlap(const Table& t, const BallState& s, double R)
{
    if (s.z <= 0.0) return cushionOverlap(t, s.position.x(), s.position.y(), R);
    // In the air the cushion is a slab up to its nose (AirborneDetection.h): below the nose its face,
    // above it the nose edge; a jaw tip is a cylinder up to the nose (its rim is not handled, so a
    // ball above it is not measured against it).
    const double x = s.position.x(), y = s.position.y(), zc = R + s.z, h = t.cushionHeight;
    double worst = -1.0;
    for (const CushionSegment& c : t.cushions) {
        double d = 0.0;
        if (!distanceOverSegment(c, x, y, d)) continue;
        if (zc <= h) worst = std::max(worst, R - d);
        else if (d >= 0.0) worst = std::max(worst, R - std::hypot(d, zc - h));
        else worst = std::max(worst, h - (zc - R));  // above the rail's top: overlaps only if below it
    }
    if (zc <= h)
        for (const JawTip& j : t.jaws) worst = std::max(worst, R + j.radius - std::hypot(x - j.centre.x(), y - j.centre.y()));
    return worst;
}

double maxOverlap(const SimulationResult& r, const std::vector<BallState>& s)
{
    // Plain doubles rather than Eigen expressions: this runs at every event of thousands of runs,
    // also in unoptimised sanitizer builds.
    double worst = -1.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (isOutOfPlay(s[i].motion)) continue;
        const double R = r.balls[i].radius;
        const double x = s[i].position.x(), y = s[i].position.y();
        for (std::size_t j = i + 1; j < s.size(); ++j) {
            if (isOutOfPlay(s[j].motion)) continue;
            const double dx = s[j].position.x() - x, dy = s[j].position.y() - y;
            if (s[i].z != 0.0 || s[j].z != 0.0) {  // in space: the centres at heights R + z
                const double Rj = r.balls[j].radius, reach = R + Rj, dz = (Rj + s[j].z) - (R + s[i].z);
                const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
                if (d < reach) worst = std::max(worst, reach - d);
                continue;
            }
            const double reach = touchDistance(R, r.balls[j].radius);  // 2 sqrt(Ri Rj): centres at Ri, Rj
            if (dx * dx + dy * dy < reach * reach) worst = std::max(worst, reach - std::sqrt(dx * dx + dy * dy));
        }
        worst = std::max(worst, cushionOverlap(r.table, s[i], R));
    }
    return worst;
}

bool insidePolygon(const std::vector<Vec2>& poly, const Vec2& p)
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

std::vector<Vec2> mouthPolygon(const Table& t, const Pocket& k, double R)
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

std::string placeProblem(const SimulationResult& r, const BallState& s, double R)
{
    const double tol = 1e-9;
    if (s.motion == MotionState::Pocketed) {
        if (s.pocket < 0 || s.pocket >= int(r.table.pockets.size())) return "pocketed in no pocket";
        if (s.position != r.table.pockets[static_cast<std::size_t>(s.pocket)].centre) return "pocketed off its pocket's centre";
        if (!s.velocity.isZero(0.0) || !s.spin.isZero(0.0)) return "pocketed and still moving";
        return {};
    }
    if (s.motion == MotionState::OffTable) {
        if (!s.velocity.isZero(0.0) || !s.spin.isZero(0.0) || s.vz != 0.0) return "off the table and still moving";
        return {};
    }
    if (s.pocket != -1) return "a pocket index on a ball on the table";
    const Vec2& p = s.position;
    if (!p.allFinite() || !std::isfinite(s.z) || !std::isfinite(s.vz)) return "not finite";
    if (s.z < -kHeightTolerance) return "under the cloth (z = " + number(s.z) + " m)";
    if (s.z <= 0.0 && s.vz < 0.0) return "on the cloth and going into it";
    if (cushionOverlap(r.table, s, R) > tol) return "overlaps a cushion or jaw";
    // A flying ball may be over a pocket or its mouth; beyond the table's outline (the playing area
    // and the pockets' circles widened by R: AirborneDetection.h's insideOutline) it has left the
    // table and must be off-table, not in play (issue 40).
    if (s.z > 0.0) {
        const bool playing = p.x() >= -tol && p.x() <= r.table.length + tol && p.y() >= -tol && p.y() <= r.table.width + tol;
        bool overPocket = false;
        for (const Pocket& k : r.table.pockets) overPocket = overPocket || (p - k.centre).norm() <= k.radius + R + tol;
        return playing || overPocket ? std::string() : "flying beyond the table's outline, still in play";
    }
    for (const Pocket& k : r.table.pockets)
        if ((p - k.centre).norm() < k.radius - tol) return "inside " + k.id + " without dropping";
    const bool cloth = p.x() >= R - tol && p.x() <= r.table.length - R + tol && p.y() >= R - tol
                       && p.y() <= r.table.width - R + tol;
    if (cloth) return {};
    for (const Pocket& k : r.table.pockets)
        if (insidePolygon(mouthPolygon(r.table, k, R), p)) return {};
    return "off the cloth and in no pocket's mouth";
}

std::string placeProblemAt(const SimulationResult& r, int index, double t, const BallState& s)
{
    std::string why = placeProblem(r, s, r.balls[static_cast<std::size_t>(index)].radius);
    if (!why.empty() || s.motion != MotionState::Pocketed) return why;
    for (const Event& e : r.events)
        if (e.kind == EventKind::BallPocket && e.balls[0] == index && e.pocket == s.pocket && e.time <= t) return {};
    return "pocketed without a pocket event";
}

double totalEnergy(const SimulationResult& r, const std::vector<BallState>& s)
{
    double e = 0.0;
    // With the height's potential energy m g z (0 on the cloth): constant in flight.
    for (std::size_t i = 0; i < s.size(); ++i) e += mechanicalEnergy(s[i], r.balls[i].radius, r.balls[i].mass, r.physics.gravity);
    return e;
}

EventEnergy eventEnergy(const SimulationResult& r, const Event& e)
{
    EventEnergy out;
    const double g = r.physics.gravity;
    auto add = [&](int index, const BallState& before, const BallState& after) {
        const Ball& b = r.balls[static_cast<std::size_t>(index)];
        out.before += mechanicalEnergy(before, b.radius, b.mass, g);
        out.after += mechanicalEnergy(after, b.radius, b.mass, g);
    };
    for (std::size_t k = 0; k < 2; ++k)
        if (e.balls[k] >= 0) add(e.balls[k], e.before[k], e.after[k]);
    for (const Event::GroupChange& c : e.group) add(c.ball, c.before, c.after);
    return out;
}

bool sameState(const BallState& a, const BallState& b)
{
    return a.position == b.position && a.velocity == b.velocity && a.spin == b.spin && a.motion == b.motion
           && a.pocket == b.pocket && a.z == b.z && a.vz == b.vz;
}

double momentumChange(const SimulationResult& r, const Event& e)
{
    if (e.kind != EventKind::BallBall || e.grouped) return 0.0;
    const Ball& A = r.balls[static_cast<std::size_t>(e.balls[0])];
    const Ball& B = r.balls[static_cast<std::size_t>(e.balls[1])];
    const Vec2 before = A.mass * e.before[0].velocity + B.mass * e.before[1].velocity;
    const Vec2 after = A.mass * e.after[0].velocity + B.mass * e.after[1].velocity;
    // A held event's hold impulse acts by Contact.h's contactResponse (a rolling ball takes 5/7 of it,
    // the cloth the rest): the pair's momentum changes by exactly (c_a - c_b) holdImpulse n, with c
    // from its law's after-states.
    // Before it, a ball the law leaves with a slip that has as good as ended rolls out (Motion.h's
    // rollOut: the cloth's impulse -2/7 m u).
    Vec2 cloth = Vec2::Zero();
    // (A flying ball held on a ball at its event changes no velocity: AirHold.cpp.)
    const bool air = e.before[0].motion == MotionState::Airborne || e.before[1].motion == MotionState::Airborne;
    if (!air && (e.held || e.holdImpulse != 0.0)) {
        const BallBallResult law = resolveBallBall({e.before[0], A.radius, A.mass}, {e.before[1], B.radius, B.mass}, r.physics);
        BallState a = law.a, b = law.b;
        auto settled = [](BallState& s, const Ball& ball, Vec2& share) {
            s.motion = classify(s, ball.radius);
            if (s.motion == MotionState::Sliding && slipHasEnded(s, ball.radius)) {
                const Vec2 v = s.velocity;
                rollOut(s, ball.radius);
                share += ball.mass * (s.velocity - v);
                s.motion = classify(s, ball.radius);
            }
        };
        settled(a, A, cloth);
        settled(b, B, cloth);
        cloth += (contactResponse(a) - contactResponse(b)) * e.holdImpulse * law.normal;
    }
    return (after - before - cloth).norm();
}

BallState continued(const SimulationResult& r, int index, const MotionSegment& seg, double t)
{
    const double R = r.balls[static_cast<std::size_t>(index)].radius;
    if (seg.pushed()) return segmentState(seg, R, r.physics, t - seg.start);  // a held push or flight
    BallState s = seg.state;
    double start = seg.start;
    if (seg.bounces) {  // a bounce series, then the cloth's motion from its end
        const BounceSeries b = bounceSeriesOf(seg.state, R, r.physics);
        if (t - seg.start < b.duration) return seriesStateAt(b, t - seg.start);
        s = b.end;
        start = seg.start + b.duration;
    }
    for (;;) {
        const Transition tr = nextTransition(s, R, r.physics);
        if (tr.after == kNever || start + tr.after > t) break;
        s = applyTransition(s, R, r.physics);
        start += tr.after;
    }
    return evolve(s, R, r.physics, t - start);
}


std::vector<int> touchingGroup(const SimulationResult& r, const std::vector<BallState>& s, int index, double gap)
{
    std::vector<int> group{index};
    std::vector<char> in(s.size(), 0);
    in[static_cast<std::size_t>(index)] = 1;
    for (std::size_t k = 0; k < group.size(); ++k) {
        const std::size_t a = static_cast<std::size_t>(group[k]);
        for (std::size_t b = 0; b < s.size(); ++b) {
            if (in[b] || s[b].motion == MotionState::Pocketed) continue;
            double d2 = (s[b].position - s[a].position).squaredNorm();
            double reach = touchDistance(r.balls[a].radius, r.balls[b].radius) + gap;
            if (s[a].z != 0.0 || s[b].z != 0.0) {  // in space: the centres at heights R + z
                const double dz = (r.balls[a].radius + s[a].z) - (r.balls[b].radius + s[b].z);
                d2 += dz * dz;
                reach = r.balls[a].radius + r.balls[b].radius + gap;
            }
            if (d2 <= reach * reach) {
                in[b] = 1;
                group.push_back(static_cast<int>(b));
            }
        }
    }
    std::sort(group.begin(), group.end());
    return group;
}

BallState stateBefore(const SimulationResult& r, int index, double t)
{
    const std::vector<MotionSegment>& tl = r.timelines.at(static_cast<std::size_t>(index));
    // The last segment that starts strictly before t (the first one when none does).
    auto it = std::lower_bound(tl.begin(), tl.end(), t, [](const MotionSegment& s, double time) { return s.start < time; });
    if (it != tl.begin()) --it;
    return continued(r, index, *it, t);
}

namespace {

// The number of bodies (balls, cushion noses, jaws) ball i touches in s, within `gap`.
int contactCount(const SimulationResult& r, const std::vector<BallState>& s, std::size_t i, double gap)
{
    if (s[i].motion == MotionState::Pocketed) return 0;
    int n = 0;
    const double R = r.balls[i].radius;
    for (std::size_t j = 0; j < s.size(); ++j) {
        if (j == i || s[j].motion == MotionState::Pocketed) continue;
        const double reach = touchDistance(R, r.balls[j].radius) + gap;
        n += (s[j].position - s[i].position).squaredNorm() <= reach * reach ? 1 : 0;
    }
    const double x = s[i].position.x(), y = s[i].position.y();
    for (const CushionSegment& c : r.table.cushions) {
        const Vec2 d = c.b - c.a;
        const double lambda = (s[i].position - c.a).dot(d) / d.squaredNorm();
        if (lambda < 0.0 || lambda > 1.0) continue;
        n += (x - c.a.x()) * c.normal.x() + (y - c.a.y()) * c.normal.y() <= R + gap ? 1 : 0;
    }
    for (const JawTip& j : r.table.jaws) n += (s[i].position - j.centre).norm() <= R + j.radius + gap ? 1 : 0;
    return n;
}

// A ball the cloth holds in place while a group is re-seated (seatContacts): labelled at rest, or
// slower than kRollOffSpeed (the solver's "rolling off from rest", Contact.h).
bool atRest(const BallState& s)
{
    return s.motion == MotionState::Stationary || s.motion == MotionState::Spinning || s.velocity.norm() < kRollOffSpeed;
}

// Whether the cloth may have held ball `index` whole in one of the solves at the instant t. Each event
// of a cascade at one instant solves its group again, from the states the solve before it left, so a
// member may pass below kRollOffSpeed between its states just before and just after the instant, and
// be held by the cloth there: seed23-shot942189's ball 2 rolled at 1.09e-9 m/s before t = 2.0123 s
// and slid at 1.16e-9 m/s after, but the hold of its contact with ball 3 at that instant left it
// rolling at 8.9e-10 m/s, and the next event's re-seating pushed ball 3 off it by 5.93e-10 N s with
// the cloth taking all of ball 2's share (contactResponse 0, rolling off from rest): the group's
// whole change. The states a solve at t starts a member from: its segments that begin at t (each what
// a solve left), the before-states of its events at t, and what the law of its ball-ball events gave
// it before their solve (the frictional laws are not checked here), each relabelled as settle()
// does (a slip that has as good as ended rolls out).
bool clothHeldDuring(const SimulationResult& r, int index, double t, const std::vector<const Event*>& events)
{
    const Ball& ball = r.balls[static_cast<std::size_t>(index)];
    auto rests = [&](BallState s) {
        if (s.motion == MotionState::Pocketed) return true;  // (no share of its own: the group is not checked)
        s.motion = classify(s, ball.radius);
        if (s.motion == MotionState::Sliding && slipHasEnded(s, ball.radius)) {
            rollOut(s, ball.radius);
            s.motion = classify(s, ball.radius);
        }
        return atRest(s);
    };
    const std::vector<MotionSegment>& tl = r.timelines[static_cast<std::size_t>(index)];
    auto it = std::lower_bound(tl.begin(), tl.end(), t, [](const MotionSegment& seg, double time) { return seg.start < time; });
    for (; it != tl.end() && it->start == t; ++it)
        if (rests(it->state)) return true;
    for (const Event* e : events) {
        for (std::size_t k = 0; k < 2; ++k)
            if (e->balls[k] == index && rests(e->before[k])) return true;
        if (e->kind != EventKind::BallBall || (e->balls[0] != index && e->balls[1] != index)) continue;
        const Ball& A = r.balls[static_cast<std::size_t>(e->balls[0])];
        const Ball& B = r.balls[static_cast<std::size_t>(e->balls[1])];
        const BallBallResult law = resolveBallBall({e->before[0], A.radius, A.mass}, {e->before[1], B.radius, B.mass}, r.physics);
        if (rests(e->balls[0] == index ? law.a : law.b)) return true;
    }
    return false;
}

}  // namespace

Vec2 clothCorrectedMomentum(const BallState& s, double radius, double mass)
{
    // The cloth touches the ball at -R z: a horizontal impulse J there turns it by
    // I dw = (-R z) x J = (R Jy, -R Jx, 0), so J = (I / R) (-dw_y, dw_x). What the ball's momentum
    // gains from every other impulse (through its centre) is then m dv - J = d[m v + (I / R) (w_y, -w_x)].
    const double k = ballInertia(mass, radius) / radius;
    return mass * s.velocity + k * Vec2(s.spin.y(), -s.spin.x());
}

std::string groupMomentumProblem(const SimulationResult& r, double* worst)
{
    // Grouped events by instant; every instant checked once, group by group. `all`: every event by instant.
    std::map<double, std::vector<const Event*>> instants, all;
    for (const Event& e : r.events) {
        all[e.time].push_back(&e);
        if (e.kind == EventKind::BallBall && e.grouped) instants[e.time].push_back(&e);
    }
    double largest = 0.0;
    // The frictional law's tangential impulse acts at the contact point, off the centres: its torque
    // is no cloth impulse, and the correction above cannot tell them apart.
    if (r.physics.ballBallModel != BallBallModel::Frictionless) instants.clear();
    for (const auto& [t, grouped] : instants) {
        const std::vector<const Event*>& here = all[t];
        const std::vector<BallState> after = r.statesAt(t);
        std::vector<char> done(after.size(), 0);
        for (const Event* g : grouped) {
            if (done[static_cast<std::size_t>(g->balls[0])]) continue;
            const std::vector<int> group = touchingGroup(r, after, g->balls[0], kHeldGap);
            bool shared = false;  // with a cushion, or with the cloth holding a ball at rest
            Vec2 before = Vec2::Zero(), now = Vec2::Zero();
            double scale = 0.0;  // N s: sum m |v| before and after
            double snap = 0.0;   // N s: sum m kSpeedEpsilon
            for (int i : group) {
                const std::size_t u = static_cast<std::size_t>(i);
                done[u] = 1;
                const BallState b = stateBefore(r, i, t);
                const double m = r.balls[u].mass, R = r.balls[u].radius;
                shared = shared || atRest(b) || atRest(after[u]) || b.motion == MotionState::Pocketed
                         || after[u].motion == MotionState::Pocketed
                         || cushionOverlap(r.table, after[u].position.x(), after[u].position.y(), R) > -kHeldGap
                         || clothHeldDuring(r, i, t, here);
                before += clothCorrectedMomentum(b, R, m);
                now += clothCorrectedMomentum(after[u], R, m);
                scale += m * (b.velocity.norm() + after[u].velocity.norm());
                snap += m * kSpeedEpsilon;
            }
            for (const Event* e : here) {  // another kind of event of a member at this instant
                if (e->kind == EventKind::BallBall) continue;
                shared = shared || std::binary_search(group.begin(), group.end(), e->balls[0]);
            }
            if (shared) continue;
            const double dp = (now - before).norm();
            largest = std::max(largest, dp);
            // Rounding of an n-ball solve (1e-12 per ball of the momenta involved), and the labels: a
            // slip below kSpeedEpsilon counts as rolling, and the spin is made to roll exactly.
            if (dp > 1e-12 * static_cast<double>(group.size()) * scale + snap + 1e-15) {
                if (worst) *worst = largest;
                return "the held group of ball " + r.balls[static_cast<std::size_t>(g->balls[0])].id + " (" +
                       std::to_string(group.size()) + " balls) at t = " + number(t) + " changes its momentum (less the cloth's share) by " +
                       number(dp) + " N s";
            }
        }
    }
    if (worst) *worst = largest;
    return {};
}

std::string timelineProblem(const SimulationResult& r, double positionTol, double velocityTol)
{
    // The balls of a held group solved at an instant: those of its held or grouped events, and those
    // whose push begins, goes on into a new segment or ends there.
    std::map<double, std::vector<int>> solved;
    for (const Event& e : r.events)
        if (e.held || e.grouped)
            for (int b : e.balls)
                if (b >= 0) solved[e.time].push_back(b);
    for (std::size_t i = 0; i < r.timelines.size(); ++i)
        for (std::size_t k = 1; k < r.timelines[i].size(); ++k)
            if (!r.timelines[i][k].push.isZero(0.0) || !r.timelines[i][k - 1].push.isZero(0.0))
                solved[r.timelines[i][k].start].push_back(static_cast<int>(i));
    // Ball `index` belongs to a group solved at t: it touches (through held gaps) one of its balls.
    auto inSolvedGroup = [&](int index, double t) {
        const auto it = solved.find(t);
        if (it == solved.end()) return false;
        const std::vector<int> group = touchingGroup(r, r.statesAt(t), index, kHeldGap);
        for (int b : it->second)
            if (std::binary_search(group.begin(), group.end(), b)) return true;
        return false;
    };
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
        // Per instant (a cascade may put thousands of segments at one time): its events of this ball,
        // the first of them, whether one is a collision or the strike, and the segments so far.
        double instant = -1.0;
        const Event* e = nullptr;
        bool kick = false;
        // A hop within kHeldGap of the cloth that the cloth takes at this instant (a ball-table event
        // lowering the ball to the cloth: AirCollisions.cpp's landing of a flying ball that touches
        // another with no approach): the documented bound of that landing, not a jump.
        bool hopTaken = false;
        std::size_t eventsHere = 0, segments = 0;
        for (std::size_t k = 0; k + 1 < tl.size(); ++k) {
            const MotionSegment& seg = tl[k + 1];
            auto where = [&] { return who + "segment " + std::to_string(k + 1) + " at t = " + number(seg.start) + ": "; };
            if (seg.start < tl[k].start) return where() + "starts before the previous one";
            if (seg.start != instant) {
                instant = seg.start;
                e = nullptr;
                kick = false;
                hopTaken = false;
                segments = 0;
                const auto range = std::equal_range(times.begin(), times.end(), seg.start);
                eventsHere = static_cast<std::size_t>(range.second - range.first);
                for (auto it = range.first; it != range.second; ++it) {
                    const Event* here = mine[static_cast<std::size_t>(it - times.begin())];
                    e = e ? e : here;
                    kick = kick || isCollision(here->kind) || here->kind == EventKind::CueStrike
                           || here->kind == EventKind::BallTable || here->kind == EventKind::BallOffTable;
                    hopTaken = hopTaken || (here->kind == EventKind::BallTable && here->balls[0] == index &&
                                            here->before[0].z > 0.0 && here->before[0].z <= kHeldGap && here->after[0].z == 0.0);
                }
            }
            ++segments;  // this ball's segments beginning at this instant, up to this one
            const bool extra = segments > eventsHere;
            // A segment of its own held group solved again: this ball's push begins, goes on or ends
            // here, or the ball touches a ball of a held or grouped event at this instant.
            auto heldHere = [&] { return seg.held || tl[k].held || inSolvedGroup(index, seg.start); };
            const BallState end = continued(r, index, tl[k], seg.start);
            const BallState& begin = seg.state;
            // A segment that only goes on with the same motion (the same push, label, velocity and
            // spin) changes nothing: the simulator may cut a timeline there when it solves a held
            // group at that instant (a ball it released a moment before, a few micrometres away).
            const bool same = (end.velocity - begin.velocity).norm() <= velocityTol && std::abs(end.vz - begin.vz) <= velocityTol
                              && (end.spin - begin.spin).norm() * r.balls[i].radius <= velocityTol;
            const bool unchanged = solved.count(seg.start) && seg.push == tl[k].push && seg.pushZ == tl[k].pushZ && begin.motion == end.motion && same;
            // A bounce series the simulator goes on with one flight at a time (another ball may come
            // near it) begins its flight where the series had the ball, with no event.
            const bool split = tl[k].bounces && !seg.bounces && same && (end.position - begin.position).norm() <= positionTol
                               && std::abs(end.z - begin.z) <= positionTol;
            if (extra && !unchanged && !split && !heldHere())
                return where() + (e ? "more segments than events of the ball at this instant"
                                  : "begins without an event of the ball and outside any held group of the ball");
            const double dp = (end.position - begin.position).norm();
            const double dv = (end.velocity - begin.velocity).norm();
            if (e && e->kind == EventKind::BallPocket) {
                // It drops where the previous motion had brought it, and then lies in the pocket.
                const double drop = (end.position - e->before[0].position).norm();
                if (drop > positionTol) return where() + "drops " + number(drop) + " m from where it rolled";
                if (begin.motion != MotionState::Pocketed) return where() + "a pocket event leaves it on the table";
                continue;
            }
            if (end.motion == MotionState::Pocketed && begin.motion != MotionState::Pocketed)
                return where() + "moves again after its pocketing";
            if (end.motion == MotionState::OffTable && begin.motion != MotionState::OffTable)
                return where() + "moves again after leaving the table";
            const double dz = std::abs(end.z - begin.z);
            const bool landedHop = hopTaken && begin.z == 0.0 && end.z <= kHeldGap;
            if (dz > positionTol && !landedHop) return where() + "jumps " + number(dz) + " m in height";
            if (dp > positionTol) return where() + "jumps " + number(dp) + " m";
            // A held group's contacts are re-seated when it is solved (Contact.h): at most kHoldSpeed
            // per contact of this ball.
            double allowed = kick ? kNever : velocityTol;
            if (dv > allowed && heldHere()) {
                const int contacts = contactCount(r, r.statesAt(seg.start), i, kHeldGap);
                allowed = std::max(velocityTol, kHoldSpeed * std::max(1, contacts));
            }
            if (dv > allowed)
                return where() + "velocity jumps " + number(dv) + " m/s (allowed " + number(allowed) + ") at a " +
                       (e ? std::string(toString(e->kind)) : std::string("re-solved push"));
        }
        std::size_t at = 1;
        for (const Event* ev : mine) {
            while (at < tl.size() && tl[at].start < ev->time) ++at;
            if (at >= tl.size() || tl[at].start != ev->time)
                return who + "its " + std::string(toString(ev->kind)) + " at t = " + number(ev->time) + " begins no segment";
        }
    }
    return {};
}

}  // namespace cuelab::testing
