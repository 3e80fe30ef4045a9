#include "BallPlacement.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cuelab {

namespace {

constexpr double kTolerance = 1e-9;  // m, overlap allowed (CONTRACT.md, core/io SetupGeometry)

double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b, Vec2* closest = nullptr)
{
    const Vec2 ab = b - a;
    const double lengthSquared = ab.squaredNorm();
    const double t = lengthSquared > 0.0 ? std::clamp((p - a).dot(ab) / lengthSquared, 0.0, 1.0) : 0.0;
    const Vec2 c = a + t * ab;
    if (closest) *closest = c;
    return (p - c).norm();
}

// The boundary of the forbidden region, for a ball of radius r: circles the centre must stay out of,
// and lines (with the side it must stay on) for the cushion noses' straight parts and the edges.
struct Circle {
    Vec2 centre;
    double radius;  // the centre must stay at least this far (plus the margin)
};
struct Line {
    Vec2 point;   // on the line where the centre may just stand
    Vec2 normal;  // unit, towards the allowed side
};

void obstacles(const Table& table, const std::vector<Ball>& balls, int ball, double r, std::vector<Circle>& circles,
               std::vector<Line>& lines)
{
    const double m = kPlacementMargin;
    for (std::size_t j = 0; j < balls.size(); ++j)
        if (static_cast<int>(j) != ball) circles.push_back({balls[j].state.position, r + balls[j].radius + m});
    for (const JawTip& jaw : table.jaws) circles.push_back({jaw.centre, r + jaw.radius + m});
    for (const Pocket& pocket : table.pockets) circles.push_back({pocket.centre, pocket.radius + m});
    for (const CushionSegment& c : table.cushions) {
        circles.push_back({c.a, r + m});
        circles.push_back({c.b, r + m});
        lines.push_back({c.a + (r + m) * c.normal, c.normal});
    }
    lines.push_back({Vec2(m, 0.0), Vec2(1.0, 0.0)});
    lines.push_back({Vec2(table.length - m, 0.0), Vec2(-1.0, 0.0)});
    lines.push_back({Vec2(0.0, m), Vec2(0.0, 1.0)});
    lines.push_back({Vec2(0.0, table.width - m), Vec2(0.0, -1.0)});
}

void circleCircle(const Circle& a, const Circle& b, std::vector<Vec2>& out)
{
    const Vec2 d = b.centre - a.centre;
    const double dist = d.norm();
    if (dist < 1e-12 || dist > a.radius + b.radius || dist < std::abs(a.radius - b.radius)) return;
    const double along = (a.radius * a.radius - b.radius * b.radius + dist * dist) / (2.0 * dist);
    const double h = std::sqrt(std::max(0.0, a.radius * a.radius - along * along));
    const Vec2 u = d / dist, v(-u.y(), u.x());
    const Vec2 base = a.centre + along * u;
    out.push_back(base + h * v);
    out.push_back(base - h * v);
}

void circleLine(const Circle& c, const Line& l, std::vector<Vec2>& out)
{
    const double s = (c.centre - l.point).dot(l.normal);  // signed distance of the centre to the line
    if (std::abs(s) > c.radius) return;
    const Vec2 foot = c.centre - s * l.normal;
    const Vec2 along(-l.normal.y(), l.normal.x());
    const double h = std::sqrt(std::max(0.0, c.radius * c.radius - s * s));
    out.push_back(foot + h * along);
    out.push_back(foot - h * along);
}

void lineLine(const Line& a, const Line& b, std::vector<Vec2>& out)
{
    // n_a . p = n_a . a.point, n_b . p = n_b . b.point
    const double det = a.normal.x() * b.normal.y() - a.normal.y() * b.normal.x();
    if (std::abs(det) < 1e-12) return;
    const double ca = a.normal.dot(a.point), cb = b.normal.dot(b.point);
    out.emplace_back((ca * b.normal.y() - a.normal.y() * cb) / det, (a.normal.x() * cb - ca * b.normal.x()) / det);
}

Vec2 projectOnCircle(const Circle& c, const Vec2& w)
{
    Vec2 d = w - c.centre;
    if (d.norm() < 1e-12) d = Vec2(1.0, 0.0);
    return c.centre + c.radius * d.normalized();
}

Vec2 projectOnLine(const Line& l, const Vec2& w) { return w - (w - l.point).dot(l.normal) * l.normal; }

// How far the boundary piece is from w (to prune the pairs worth intersecting).
double reach(const Circle& c, const Vec2& w) { return std::abs((w - c.centre).norm() - c.radius); }
double reach(const Line& l, const Vec2& w) { return std::abs((w - l.point).dot(l.normal)); }

}  // namespace

bool isLegalSpot(const Table& table, const std::vector<Ball>& balls, int ball, const Vec2& p)
{
    if (ball < 0 || static_cast<std::size_t>(ball) >= balls.size()) return false;
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return false;
    const double r = balls[static_cast<std::size_t>(ball)].radius;
    if (p.x() < 0.0 || p.x() > table.length || p.y() < 0.0 || p.y() > table.width) return false;
    for (const Pocket& pocket : table.pockets)
        if ((p - pocket.centre).norm() < pocket.radius) return false;
    for (const CushionSegment& c : table.cushions)
        if (r - distanceToSegment(p, c.a, c.b) > kTolerance) return false;
    for (const JawTip& jaw : table.jaws)
        if (r + jaw.radius - (p - jaw.centre).norm() > kTolerance) return false;
    for (std::size_t j = 0; j < balls.size(); ++j) {
        if (static_cast<int>(j) == ball) continue;
        if (r + balls[j].radius - (p - balls[j].state.position).norm() > kTolerance) return false;
    }
    return true;
}

std::optional<Vec2> nearestLegalSpot(const Table& table, const std::vector<Ball>& balls, int ball, const Vec2& wanted)
{
    if (ball < 0 || static_cast<std::size_t>(ball) >= balls.size()) return std::nullopt;
    if (!std::isfinite(wanted.x()) || !std::isfinite(wanted.y())) return std::nullopt;
    // Far off the table: start from the nearest point of the surface, as a drag past the rail means.
    const Vec2 w(std::clamp(wanted.x(), 0.0, table.length), std::clamp(wanted.y(), 0.0, table.width));
    if (isLegalSpot(table, balls, ball, w)) return w;
    const double r = balls[static_cast<std::size_t>(ball)].radius;
    std::vector<Circle> circles;
    std::vector<Line> lines;
    obstacles(table, balls, ball, r, circles, lines);

    std::optional<Vec2> best;
    double bestDistance = std::numeric_limits<double>::infinity();
    auto consider = [&](const Vec2& p) {
        const double d = (p - w).norm();
        if (d < bestDistance && isLegalSpot(table, balls, ball, p)) {
            bestDistance = d;
            best = p;
        }
    };
    // Projections onto one boundary piece.
    for (const Circle& c : circles) consider(projectOnCircle(c, w));
    for (const Line& l : lines) consider(projectOnLine(l, w));
    // Corners where two pieces meet, among the pieces that come nearer to w than the best so far.
    std::vector<const Circle*> nearCircles;
    std::vector<const Line*> nearLines;
    for (const Circle& c : circles)
        if (reach(c, w) < bestDistance) nearCircles.push_back(&c);
    for (const Line& l : lines)
        if (reach(l, w) < bestDistance) nearLines.push_back(&l);
    std::vector<Vec2> corners;
    for (std::size_t i = 0; i < nearCircles.size(); ++i) {
        for (std::size_t j = i + 1; j < nearCircles.size(); ++j) circleCircle(*nearCircles[i], *nearCircles[j], corners);
        for (const Line* l : nearLines) circleLine(*nearCircles[i], *l, corners);
    }
    for (std::size_t i = 0; i < nearLines.size(); ++i)
        for (std::size_t j = i + 1; j < nearLines.size(); ++j) lineLine(*nearLines[i], *nearLines[j], corners);
    for (const Vec2& p : corners) consider(p);
    return best;
}

std::optional<Vec2> constrainedPlacement(const SimulationResult& result, int ball, const Vec2& wanted)
{
    return nearestLegalSpot(result.table, result.balls, ball, wanted);
}

}  // namespace cuelab
