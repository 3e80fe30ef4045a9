#include "Aim.h"

#include "BallContact.h"
#include "Event.h"

#include <cmath>
#include <numbers>

namespace cuelab::aim {

namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// (−180, 180]
double wrapDegrees(double deg)
{
    double w = std::remainder(deg, 360.0);
    if (w <= -180.0) w += 360.0;
    return w;
}

}  // namespace

AimGeometry geometryAt(const Vec2& ghost, const Vec2& path, const Vec2& object, double struckRadius,
                       double objectRadius, const Vec2& aimStart)
{
    AimGeometry g;
    g.ghostBall = ghost;
    g.objectBall = object;
    g.aimStart = aimStart;
    const Vec2 centres = object - ghost;
    g.lineOfCentres = centres.norm() > 0.0 ? Vec2(centres / centres.norm()) : Vec2(1.0, 0.0);
    g.path = path.norm() > 0.0 ? Vec2(path / path.norm()) : g.lineOfCentres;
    // atan2 of the cross and dot products: accurate at 0° (a full hit) where acos loses half the digits.
    const double signedCut = std::atan2(cross(g.path, g.lineOfCentres), g.path.dot(g.lineOfCentres)) * kDegrees;
    g.cutAngleDeg = std::abs(signedCut);
    g.ballFraction = g.cutAngleDeg >= 90.0 ? 0.0 : 1.0 - std::sin(g.cutAngleDeg / kDegrees);
    g.side = signedCut > 0.0 ? CutSide::Left : signedCut < 0.0 ? CutSide::Right : CutSide::Straight;
    // The contact lies R_s c along n from the ghost, c = D / (R_s + R_o) (1 for equal radii).
    const double c = touchDistance(struckRadius, objectRadius) / (struckRadius + objectRadius);
    g.contactPoint = ghost + struckRadius * c * g.lineOfCentres;
    g.contactOnStruckDeg = signedCut;
    g.contactOnObjectDeg = wrapDegrees(signedCut + 180.0);
    return g;
}

std::optional<AimGeometry> plannedContact(const Vec2& from, double headingDeg, const Vec2& object,
                                          double struckRadius, double objectRadius)
{
    const double D = touchDistance(struckRadius, objectRadius);
    const Vec2 u(std::cos(headingDeg / kDegrees), std::sin(headingDeg / kDegrees));
    const Vec2 toObject = object - from;
    if (toObject.norm() <= D) return std::nullopt;  // touching already
    // |from + t u − O|² = D²: t = u·(O − C) − √(D² − b²), b the path's distance from O.
    const double along = u.dot(toObject);
    const double b = cross(u, toObject);
    const double disc = D * D - b * b;
    if (along <= 0.0 || disc < 0.0) return std::nullopt;
    const double t = along - std::sqrt(disc);
    if (t < 0.0) return std::nullopt;
    return geometryAt(Vec2(from + t * u), u, object, struckRadius, objectRadius, from);
}

std::optional<double> headingForCut(const Vec2& from, const Vec2& object, double struckRadius, double objectRadius,
                                    double cutDeg, CutSide side)
{
    const double D = touchDistance(struckRadius, objectRadius);
    const Vec2 toObject = object - from;
    const double d = toObject.norm();
    if (d <= D || !(cutDeg >= 0.0 && cutDeg < 90.0)) return std::nullopt;
    const double bearing = std::atan2(toObject.y(), toObject.x()) * kDegrees;
    const double offset = std::asin(D * std::sin(cutDeg / kDegrees) / d) * kDegrees;
    // A cut to the left: the path passes to the right of O, the heading turns clockwise.
    const double sign = side == CutSide::Left ? -1.0 : side == CutSide::Right ? 1.0 : 0.0;
    return wrapDegrees(bearing + sign * offset);
}

std::optional<AimGeometry> contactOfEvent(const SimulationResult& result, int index)
{
    if (index < 0 || index >= static_cast<int>(result.events.size())) return std::nullopt;
    const Event& ev = result.events[static_cast<std::size_t>(index)];
    if (ev.kind != EventKind::BallBall) return std::nullopt;
    const Ball& a = result.balls.at(static_cast<std::size_t>(ev.balls[0]));
    const Ball& b = result.balls.at(static_cast<std::size_t>(ev.balls[1]));
    // The path: the ball's own velocity (the contract's "cue ball's path"); a ball at rest struck by
    // a moving one is read along the approach, v_a − v_b.
    Vec2 path = ev.before[0].velocity;
    if (path.norm() == 0.0) path = ev.before[0].velocity - ev.before[1].velocity;
    // The aim line starts where the ball's present straight run began: its last event before this one.
    Vec2 start = a.state.position;
    for (int k = index - 1; k >= 0; --k) {
        const Event& prev = result.events[static_cast<std::size_t>(k)];
        if (prev.kind == EventKind::CueStrike && prev.balls[0] == ev.balls[0]) { start = prev.after[0].position; break; }
        if (prev.kind == EventKind::BallBall || prev.kind == EventKind::BallCushion || prev.kind == EventKind::BallJaw) {
            if (prev.balls[0] == ev.balls[0]) { start = prev.after[0].position; break; }
            if (prev.balls[1] == ev.balls[0]) { start = prev.after[1].position; break; }
        }
    }
    return geometryAt(ev.before[0].position, path, ev.before[1].position, a.radius, b.radius, start);
}

std::optional<AimGeometry> firstContact(const SimulationResult& result, int* eventIndex, int* objectBall)
{
    if (result.events.empty() || result.events.front().kind != EventKind::CueStrike) return std::nullopt;
    const int struck = result.events.front().balls[0];
    for (std::size_t k = 1; k < result.events.size(); ++k) {
        const Event& ev = result.events[k];
        if (ev.kind != EventKind::BallBall || (ev.balls[0] != struck && ev.balls[1] != struck)) continue;
        const bool first = ev.balls[0] == struck;
        std::optional<AimGeometry> g;
        const Ball& s = result.balls.at(static_cast<std::size_t>(struck));
        const int other = first ? ev.balls[1] : ev.balls[0];
        const Ball& o = result.balls.at(static_cast<std::size_t>(other));
        const BallState& sb = ev.before[first ? 0 : 1];
        const BallState& ob = ev.before[first ? 1 : 0];
        Vec2 path = sb.velocity;
        if (path.norm() == 0.0) path = sb.velocity - ob.velocity;
        // The aim line: from where the strike left the ball (a cushion first: from its last cushion).
        Vec2 start = result.events.front().after[0].position;
        for (std::size_t j = k - 1; j > 0; --j) {
            const Event& prev = result.events[j];
            if ((prev.kind == EventKind::BallCushion || prev.kind == EventKind::BallJaw) && prev.balls[0] == struck) {
                start = prev.after[0].position;
                break;
            }
        }
        g = geometryAt(sb.position, path, ob.position, s.radius, o.radius, start);
        if (eventIndex) *eventIndex = static_cast<int>(k);
        if (objectBall) *objectBall = other;
        return g;
    }
    return std::nullopt;
}

std::optional<Launch> launchOf(const SimulationResult& result)
{
    if (result.events.empty() || result.events.front().kind != EventKind::CueStrike) return std::nullopt;
    const Event& strike = result.events.front();
    Launch l;
    l.ball = strike.balls[0];
    l.velocity = strike.after[0].velocity;
    l.speed = l.velocity.norm();
    l.spin = strike.after[0].spin;
    if (l.speed > 0.0) {
        const Vec2 d = l.velocity / l.speed;
        // z × d = (−d_y, d_x): the horizontal axis across the path; rolling forward spins about it.
        l.topspin = l.spin.x() * -d.y() + l.spin.y() * d.x();
    }
    l.sideSpin = l.spin.z();
    return l;
}

}  // namespace cuelab::aim
