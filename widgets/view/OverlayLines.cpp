#include "OverlayLines.h"

#include "CueImpact.h"

#include "BallAppearance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace cuelab {

namespace {

constexpr double kPathSampleStep = 1.0 / 120.0;  // s between path samples on curved segments
constexpr float kClothLift = 0.0015f;            // m: paths lie just above the cloth
constexpr int kFlightSamples = 24;               // samples at least per flight (one hop of a bounce)
constexpr double kPaleHeight = 0.06;             // m: a path this high (about a ball) is drawn palest
const QVector4D kShadowColour(0.0f, 0.0f, 0.0f, 0.45f);  // a flight's path on the cloth beneath it

// A path's colour at height z (m): the ball's colour, paler the higher it flies.
QVector4D heightColour(const QVector3D& c, double z)
{
    const auto pale = static_cast<float>(0.65 * std::clamp(z / kPaleHeight, 0.0, 1.0));
    return QVector4D(c + pale * (QVector3D(1.0f, 1.0f, 1.0f) - c), 0.95f);
}

QVector3D at(const Vec2& p, double z)
{
    return QVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(z));
}

QVector3D at(const Vec3& p)
{
    return QVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()));
}

void segment(std::vector<LineVertex>& out, const QVector3D& a, const QVector3D& b, const QVector4D& colour,
             float time = -1.0f)
{
    out.push_back({a, colour, time, 0.0f});
    out.push_back({b, colour, time, 0.0f});
}

// A circle of `radius` about `centre` in the plane spanned by the unit vectors u, v, from angle a0
// to a1 (radians).
void arc(std::vector<LineVertex>& out, const QVector3D& centre, const QVector3D& u, const QVector3D& v, float radius,
         double a0, double a1, int steps, const QVector4D& colour, float time = -1.0f)
{
    for (int k = 0; k < steps; ++k) {
        const double s0 = a0 + (a1 - a0) * k / steps, s1 = a0 + (a1 - a0) * (k + 1) / steps;
        segment(out, centre + radius * (static_cast<float>(std::cos(s0)) * u + static_cast<float>(std::sin(s0)) * v),
                centre + radius * (static_cast<float>(std::cos(s1)) * u + static_cast<float>(std::sin(s1)) * v), colour,
                time);
    }
}

void ring(std::vector<LineVertex>& out, const QVector3D& centre, float radius, const QVector4D& colour,
          float time = -1.0f)
{
    arc(out, centre, QVector3D(1, 0, 0), QVector3D(0, 1, 0), radius, 0.0, 2.0 * std::numbers::pi, 20, colour, time);
}

// An arrow from a to b; the barbs of its head lie in the plane of the shaft and `side`.
void arrow(std::vector<LineVertex>& out, const QVector3D& a, const QVector3D& b, const QVector3D& side,
           const QVector4D& colour, float time = -1.0f)
{
    const QVector3D shaft = b - a;
    const float length = shaft.length();
    if (length < 1e-5f) return;
    segment(out, a, b, colour, time);
    const QVector3D dir = shaft / length;
    const float head = std::min(0.35f * length, 0.03f);
    const QVector3D back = b - head * dir;
    segment(out, b, back + 0.45f * head * side, colour, time);
    segment(out, b, back - 0.45f * head * side, colour, time);
}

double ballRadius(const SimulationResult& result, int i) { return result.balls[static_cast<std::size_t>(i)].radius; }

QVector4D eventColour(EventKind kind)
{
    switch (kind) {
    case EventKind::BallBall: return {1.0f, 0.62f, 0.12f, 1.0f};
    case EventKind::BallCushion:
    case EventKind::BallJaw: return {0.35f, 0.85f, 1.0f, 1.0f};
    case EventKind::BallPocket: return {1.0f, 0.35f, 0.85f, 1.0f};
    default: return {1.0f, 1.0f, 1.0f, 1.0f};
    }
}

bool involves(const Event& ev, int ball) { return ball < 0 || ev.balls[0] == ball || ev.balls[1] == ball; }

}  // namespace

void buildPathLines(const SimulationResult& result, std::vector<LineVertex>& out, int onlyBall)
{
    out.clear();
    for (std::size_t i = 0; i < result.balls.size() && i < result.timelines.size(); ++i) {
        const int index = static_cast<int>(i);
        if (onlyBall >= 0 && index != onlyBall) continue;
        const std::vector<MotionSegment>& timeline = result.timelines[i];
        const BallLook look = ballLook(result.table.kind, result.balls[i].id);
        const QVector3D c = pathColour(look, result.table.kind);
        double travelled = 0.0;
        for (std::size_t k = 0; k < timeline.size(); ++k) {
            const MotionSegment& seg = timeline[k];
            if (isOutOfPlay(seg.state.motion)) break;
            const double end = k + 1 < timeline.size() ? timeline[k + 1].start : result.endTime;
            if (end <= seg.start) continue;
            // No travel (resting or spinning); a flight straight up and down still has a height to show.
            if (seg.state.velocity.squaredNorm() < 1e-20 && seg.push.isZero(0.0) && seg.state.motion != MotionState::Airborne)
                continue;
            // Rolling and uniform motion go straight; sliding curves (a parabola), so sample it. A
            // flight is a parabola in height too, often only milliseconds long (a bounce): never
            // fewer than kFlightSamples samples, so that each hop shows as an arc.
            const bool straight = seg.state.motion == MotionState::Rolling && seg.push.isZero(0.0);
            const bool flight = seg.state.motion == MotionState::Airborne;
            int steps = straight ? 1 : std::clamp(static_cast<int>(std::ceil((end - seg.start) / kPathSampleStep)), 1, 2000);
            if (flight) steps = std::max(steps, kFlightSamples);
            Vec2 previous = seg.state.position;
            double previousHeight = seg.state.z;
            double previousTime = seg.start;
            for (int s = 1; s <= steps; ++s) {
                const double t = seg.start + (end - seg.start) * s / steps;
                // The state at the end of a segment is the start of the next one (just after its
                // event); the end point of this one is its limit, evaluated a hair before.
                const double sampleTime = s == steps ? std::nextafter(t, seg.start) : t;
                const BallState state = result.stateAt(index, sampleTime);
                if (isOutOfPlay(state.motion)) break;
                const double step = (state.position - previous).norm();
                // In flight the path is drawn at the centre's height above its resting height (an arc
                // seen from the side), paler the higher it is (readable from above), over its shadow.
                if (flight || previousHeight > 0.0 || state.z > 0.0) {
                    out.push_back({at(previous, kClothLift), kShadowColour, static_cast<float>(previousTime),
                                   static_cast<float>(travelled)});
                    out.push_back({at(state.position, kClothLift), kShadowColour, static_cast<float>(t),
                                   static_cast<float>(travelled + step)});
                }
                out.push_back({at(previous, kClothLift + previousHeight), heightColour(c, previousHeight),
                               static_cast<float>(previousTime), static_cast<float>(travelled)});
                travelled += step;
                out.push_back({at(state.position, kClothLift + state.z), heightColour(c, state.z), static_cast<float>(t),
                               static_cast<float>(travelled)});
                previous = state.position;
                previousHeight = state.z;
                previousTime = t;
            }
        }
    }
}

void buildEventMarkers(const SimulationResult& result, int highlightedEvent, std::vector<LineVertex>& out, int onlyBall)
{
    out.clear();
    for (std::size_t e = 0; e < result.events.size(); ++e) {
        const Event& ev = result.events[e];
        if (!isCollision(ev.kind) && ev.kind != EventKind::BallPocket) continue;
        if (!involves(ev, onlyBall) && static_cast<int>(e) != highlightedEvent) continue;
        const double r = ev.balls[0] >= 0 ? ballRadius(result, ev.balls[0]) : result.table.ballRadius;
        const Vec2 point = ev.kind == EventKind::BallPocket ? ev.before[0].position : ev.contactPoint;
        const QVector3D centre = at(point, r);
        const auto time = static_cast<float>(ev.time);
        if (static_cast<int>(e) == highlightedEvent) {
            const QVector4D yellow(1.0f, 0.95f, 0.2f, 1.0f);
            ring(out, centre, 0.022f, yellow, -1.0f);
            ring(out, centre, 0.030f, yellow, -1.0f);
        } else {
            ring(out, centre, 0.013f, eventColour(ev.kind), time);
        }
    }
}

void buildGhostLines(const SimulationResult& result, std::vector<LineVertex>& out, int onlyBall)
{
    out.clear();
    for (const Event& ev : result.events) {
        if (ev.kind != EventKind::BallBall || !involves(ev, onlyBall)) continue;
        const double r = ballRadius(result, ev.balls[0]);
        const Vec2 a = ev.before[0].position, b = ev.before[1].position;
        const Vec2 dir = (b - a).normalized();
        const auto time = static_cast<float>(ev.time);
        // The line of centres, through the object ball and on, where a frictionless hit sends it.
        segment(out, at(a, r + ev.before[0].z), at(b + 0.18 * dir, r + ev.before[1].z), QVector4D(0.95f, 0.95f, 0.95f, 0.85f),
                time);
        // The contact normal at the contact point.
        const QVector3D contact = at(ev.contactPoint, r + 0.5 * (ev.before[0].z + ev.before[1].z));
        const QVector3D n = at(ev.normal, 0.0);
        arrow(out, contact, contact + 0.07f * n, QVector3D(-n.y(), n.x(), 0.0f), QVector4D(1.0f, 0.35f, 0.3f, 1.0f), time);
    }
}

std::vector<GhostBall> ghostBalls(const SimulationResult& result, int onlyBall)
{
    std::vector<GhostBall> ghosts;
    for (std::size_t e = 0; e < result.events.size(); ++e) {
        const Event& ev = result.events[e];
        if (ev.kind != EventKind::BallBall || !involves(ev, onlyBall)) continue;
        const auto r = static_cast<float>(ballRadius(result, ev.balls[0]));
        ghosts.push_back({at(ev.before[0].position, r + ev.before[0].z), r, static_cast<int>(e)});
    }
    return ghosts;
}

void appendVelocityArrows(const SimulationResult& result, const std::vector<BallState>& states,
                          std::vector<LineVertex>& out)
{
    const QVector4D colour(1.0f, 0.93f, 0.3f, 1.0f);
    for (std::size_t i = 0; i < states.size(); ++i) {
        const BallState& s = states[i];
        // In 3-D: a flying ball's arrow tilts up or down with vz.
        const Vec3 v(s.velocity.x(), s.velocity.y(), s.vz);
        if (isOutOfPlay(s.motion) || v.norm() < 1e-3) continue;
        const double r = result.balls[i].radius;
        const Vec3 from(s.position.x(), s.position.y(), r + s.z + 0.002);
        const QVector3D a = at(from);
        const QVector3D b = at(Vec3(from + kVelocityArrowScale * v));
        const Vec2 d = s.velocity.norm() > 0.0 ? Vec2(s.velocity.normalized()) : Vec2(1.0, 0.0);
        arrow(out, a, b, QVector3D(static_cast<float>(-d.y()), static_cast<float>(d.x()), 0.0f), colour);
    }
}

void appendSpinIndicators(const SimulationResult& result, const std::vector<BallState>& states,
                          std::vector<LineVertex>& out)
{
    const QVector4D colour(0.35f, 0.95f, 1.0f, 1.0f);
    for (std::size_t i = 0; i < states.size(); ++i) {
        const BallState& s = states[i];
        const double w = s.spin.norm();
        if (isOutOfPlay(s.motion) || w < 0.3) continue;
        const auto r = static_cast<float>(result.balls[i].radius);
        const QVector3D centre = at(s.position, r + s.z);
        const QVector3D axis = at(Vec3(s.spin / w));
        // The axis pokes out of the ball further the faster it spins (up to 60 rad/s).
        const float reach = r * (1.2f + 0.9f * static_cast<float>(std::min(w / 60.0, 1.0)));
        segment(out, centre - reach * axis, centre + reach * axis, colour);
        // An arc of three quarters of a turn about the axis, in the sense of the rotation
        // (right-handed about the axis), with an arrowhead at its end.
        QVector3D u = QVector3D::crossProduct(axis, QVector3D(0, 0, 1));
        if (u.lengthSquared() < 1e-6f) u = QVector3D(1, 0, 0);
        u.normalize();
        const QVector3D v = QVector3D::crossProduct(axis, u);
        const float radius = 1.35f * r;
        const QVector3D arcCentre = centre + 0.55f * reach * axis;
        const double end = 1.5 * std::numbers::pi;
        arc(out, arcCentre, u, v, radius, 0.0, end, 18, colour);
        const QVector3D tip = arcCentre + radius * (static_cast<float>(std::cos(end)) * u + static_cast<float>(std::sin(end)) * v);
        const QVector3D tangent = -static_cast<float>(std::sin(end)) * u + static_cast<float>(std::cos(end)) * v;
        const QVector3D radial = (tip - arcCentre).normalized();
        const float head = 0.5f * r;
        segment(out, tip, tip - head * tangent + 0.5f * head * radial, colour);
        segment(out, tip, tip - head * tangent - 0.5f * head * radial, colour);
    }
}

void appendAimLines(const SimulationResult& result, const std::optional<CueStrike>& shot, std::vector<LineVertex>& out)
{
    for (std::size_t i = 0; i < result.balls.size(); ++i) {
        const int index = static_cast<int>(i);
        // The state just after t = 0: after the cue strike, or the file's initial motion.
        const BallState s = result.timelines.empty() ? result.balls[i].state : result.stateAt(index, 0.0);
        if (s.motion == MotionState::Pocketed || s.velocity.norm() < 1e-6) continue;
        const Vec2 from = result.balls[i].state.position;
        appendAimLine(result, index, from, s.velocity.normalized(), out);
        // Squirt (shot.end_mass, Alciatore TP A-31): the dashed line is the ball's real start
        // direction; the cue line (the heading) is drawn solid orange beside it, so the angle between
        // the two is the squirt.
        if (!shot || shot->ball != result.balls[i].id) continue;
        if (squirtAngle(shot->side, result.balls[i].mass, shot->endMass) == 0.0) continue;
        const double heading = shot->headingDeg * std::numbers::pi / 180.0;
        const Vec2 cue(std::cos(heading), std::sin(heading));
        const double r = ballRadius(result, index);
        segment(out, at(from + r * cue, r), at(from + 0.6 * cue, r), QVector4D(1.0f, 0.55f, 0.1f, 0.95f));
    }
}

void appendAimLine(const SimulationResult& result, int ball, const Vec2& from, const Vec2& d, std::vector<LineVertex>& out)
{
    if (ball < 0 || static_cast<std::size_t>(ball) >= result.balls.size()) return;
    const double r = ballRadius(result, ball);
    // How far the ball travels straight before it meets a cushion (the rectangle its centre can
    // reach) or another ball (centre distance 2R: ray against a circle).
    double reach = std::numeric_limits<double>::infinity();
    const Table& t = result.table;
    for (int axis = 0; axis < 2; ++axis) {
        const double lo = r, hi = (axis == 0 ? t.length : t.width) - r;
        if (std::abs(d[axis]) > 1e-12) reach = std::min(reach, ((d[axis] > 0 ? hi : lo) - from[axis]) / d[axis]);
    }
    int hit = -1;
    for (std::size_t j = 0; j < result.balls.size(); ++j) {
        if (static_cast<int>(j) == ball) continue;
        const Vec2 m = result.balls[j].state.position - from;
        const double contact = r + result.balls[j].radius;
        const double along = m.dot(d);
        const double offset2 = m.squaredNorm() - along * along;
        if (along <= 0 || offset2 > contact * contact) continue;
        const double at1 = along - std::sqrt(contact * contact - offset2);
        if (at1 < reach) {
            reach = std::max(at1, 0.0);
            hit = static_cast<int>(j);
        }
    }
    if (!std::isfinite(reach)) return;
    const QVector4D white(1.0f, 1.0f, 1.0f, 0.9f);
    const double dash = 0.025, gap = 0.015;
    for (double a = r; a < reach; a += dash + gap)
        segment(out, at(from + a * d, r), at(from + std::min(a + dash, reach) * d, r), white);
    if (hit >= 0) {
        const QVector3D ghost = at(from + reach * d, r);
        arc(out, ghost, QVector3D(1, 0, 0), QVector3D(0, 1, 0), static_cast<float>(r), 0.0, 2.0 * std::numbers::pi, 32, white);
    }
}

void appendVelocityDragArrow(const SimulationResult& result, int ball, const Vec2& from, const Vec2& velocity,
                             std::vector<LineVertex>& out)
{
    if (ball < 0 || static_cast<std::size_t>(ball) >= result.balls.size()) return;
    const double r = ballRadius(result, ball);
    const QVector3D a = at(from, r + 0.003), b = at(from + kVelocityArrowScale * velocity, r + 0.003);
    if (velocity.norm() < 1e-6) {
        ring(out, a, 0.35f * static_cast<float>(r), QVector4D(1.0f, 0.55f, 0.1f, 1.0f));
        return;
    }
    const Vec2 d = velocity.normalized();
    arrow(out, a, b, QVector3D(static_cast<float>(-d.y()), static_cast<float>(d.x()), 0.0f), QVector4D(1.0f, 0.55f, 0.1f, 1.0f));
    appendAimLine(result, ball, from, d, out);
}

void appendSelectionRing(const SimulationResult& result, const std::vector<BallState>& states, int ball,
                         std::vector<LineVertex>& out)
{
    if (ball < 0 || static_cast<std::size_t>(ball) >= states.size()) return;
    const BallState& s = states[static_cast<std::size_t>(ball)];
    if (isOutOfPlay(s.motion)) return;
    const auto r = static_cast<float>(result.balls[static_cast<std::size_t>(ball)].radius);
    ring(out, at(s.position, kClothLift), 1.45f * r, QVector4D(1.0f, 0.85f, 0.15f, 1.0f));
}

}  // namespace cuelab
