#include "LegalPlacement.h"

#include "BallContact.h"
#include "LegalGeometry.h"
#include "LegalSetup.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cuelab {

namespace {

// A boundary of the forbidden region, grown by the gap: a circle (around a ball, a jaw tip, a pocket
// or the end of a cushion nose) or a line (a cushion nose moved out by the radius, an edge of the
// playing surface).
struct Circle {
    Vec2 centre;
    double radius;
};
struct Line {
    Vec2 point;
    Vec2 direction;  // unit
};

struct Boundaries {
    std::vector<Circle> circles;
    std::vector<Line> lines;
};

Boundaries boundariesOf(const Table& table, const std::vector<Ball>& others, double r, double gap, int skip)
{
    Boundaries b;
    b.lines.push_back({Vec2(gap, 0.0), Vec2(0.0, 1.0)});
    b.lines.push_back({Vec2(table.length - gap, 0.0), Vec2(0.0, 1.0)});
    b.lines.push_back({Vec2(0.0, gap), Vec2(1.0, 0.0)});
    b.lines.push_back({Vec2(0.0, table.width - gap), Vec2(1.0, 0.0)});
    for (const CushionSegment& c : table.cushions) {
        const Vec2 along = c.b - c.a;
        if (along.squaredNorm() > 0.0) {
            const Vec2 d = along.normalized();
            b.lines.push_back({c.a + (r + gap) * c.normal, d});
            b.lines.push_back({c.a - (r + gap) * c.normal, d});
        }
        b.circles.push_back({c.a, r + gap});
        b.circles.push_back({c.b, r + gap});
    }
    for (const JawTip& jaw : table.jaws) b.circles.push_back({jaw.centre, r + jaw.radius + gap});
    for (const Pocket& pocket : table.pockets) b.circles.push_back({pocket.centre, pocket.radius + gap});
    for (std::size_t j = 0; j < others.size(); ++j) {
        if (static_cast<int>(j) == skip) continue;
        b.circles.push_back({others[j].state.position, touchDistance(r, others[j].radius) + gap});
    }
    return b;
}

double distanceTo(const Circle& c, const Vec2& w) { return std::abs((w - c.centre).norm() - c.radius); }
double distanceTo(const Line& l, const Vec2& w)
{
    const Vec2 n(-l.direction.y(), l.direction.x());
    return std::abs((w - l.point).dot(n));
}

// The points of a boundary where the distance to w is stationary.
void projections(const Circle& c, const Vec2& w, std::vector<Vec2>& out)
{
    const Vec2 d = w - c.centre;
    if (d.norm() > 1e-12) {
        const Vec2 u = d.normalized();
        out.push_back(c.centre + c.radius * u);
        out.push_back(c.centre - c.radius * u);
        return;
    }
    for (int k = 0; k < 8; ++k) {  // w at the centre: every point is as near; try a few
        const double a = k * 0.25 * 3.14159265358979323846;
        out.push_back(c.centre + c.radius * Vec2(std::cos(a), std::sin(a)));
    }
}
void projections(const Line& l, const Vec2& w, std::vector<Vec2>& out)
{
    out.push_back(l.point + (w - l.point).dot(l.direction) * l.direction);
}

void intersections(const Circle& a, const Circle& b, std::vector<Vec2>& out)
{
    const Vec2 d = b.centre - a.centre;
    const double dist = d.norm();
    if (dist < 1e-15 || dist > a.radius + b.radius || dist < std::abs(a.radius - b.radius)) return;
    // Along the line of centres by x from a, then off it by h on either side.
    const double x = (dist * dist + a.radius * a.radius - b.radius * b.radius) / (2.0 * dist);
    const double h = std::sqrt(std::max(0.0, a.radius * a.radius - x * x));
    const Vec2 u = d / dist;
    const Vec2 n(-u.y(), u.x());
    out.push_back(a.centre + x * u + h * n);
    out.push_back(a.centre + x * u - h * n);
}
void intersections(const Circle& c, const Line& l, std::vector<Vec2>& out)
{
    const Vec2 foot = l.point + (c.centre - l.point).dot(l.direction) * l.direction;
    const double offset = (c.centre - foot).norm();
    if (offset > c.radius) return;
    const double h = std::sqrt(std::max(0.0, c.radius * c.radius - offset * offset));
    out.push_back(foot + h * l.direction);
    out.push_back(foot - h * l.direction);
}
void intersections(const Line& a, const Line& b, std::vector<Vec2>& out)
{
    const double cross = a.direction.x() * b.direction.y() - a.direction.y() * b.direction.x();
    if (std::abs(cross) < 1e-12) return;
    const Vec2 d = b.point - a.point;
    const double t = (d.x() * b.direction.y() - d.y() * b.direction.x()) / cross;
    out.push_back(a.point + t * a.direction);
}

// Every margin of a ball at p, the smallest one: >= gap means clear of everything by the gap.
double smallestMargin(const Table& table, const std::vector<Ball>& others, double r, const Vec2& p, int skip)
{
    const legal::TableMargins m = legal::tableMargins(table, r, p);
    double margin = std::min({m.surface, m.pocket, m.contact});
    for (std::size_t j = 0; j < others.size(); ++j) {
        if (static_cast<int>(j) == skip) continue;
        const double dist = (p - others[j].state.position).norm();
        // Equal radii keep the subtraction order of before unequal radii were handled.
        margin = std::min(margin, r == others[j].radius ? dist - r - others[j].radius
                                                        : dist - touchDistance(r, others[j].radius));
    }
    return margin;
}

}  // namespace

bool isLegalSpot(const Table& table, const std::vector<Ball>& others, double radius, const Vec2& p, int skip)
{
    if (!p.allFinite() || !(radius > 0.0) || table.cushionHeight >= 2.0 * radius) return false;
    const legal::TableMargins m = legal::tableMargins(table, radius, p);
    if (m.surface < 0.0 || m.pocket < 0.0 || -m.contact > kOverlapTolerance) return false;
    for (std::size_t j = 0; j < others.size(); ++j) {
        if (static_cast<int>(j) == skip) continue;
        const double overlap = touchDistance(radius, others[j].radius) - (p - others[j].state.position).norm();
        if (overlap > kOverlapTolerance) return false;
    }
    return true;
}

std::optional<Vec2> nearestLegalSpot(const Table& table, const std::vector<Ball>& others, double radius,
                                     const Vec2& wanted, double gap, int skip)
{
    if (!(radius > 0.0) || !std::isfinite(radius) || table.cushionHeight >= 2.0 * radius || legal::railsProblem(table))
        return std::nullopt;
    if (isLegalSpot(table, others, radius, wanted, skip)) return wanted;
    gap = std::max(gap, 0.0);

    Vec2 w = wanted;
    if (!w.allFinite()) w = Vec2(0.5 * table.length, 0.5 * table.width);
    // A candidate lies on a grown boundary up to rounding (a few ulps of coordinates of a few metres).
    const double slack = 1e-12;
    const auto clear = [&](const Vec2& p) { return smallestMargin(table, others, radius, p, skip) >= gap - slack; };

    const Boundaries all = boundariesOf(table, others, radius, gap, skip);
    std::optional<Vec2> best;
    double bestDistance = std::numeric_limits<double>::infinity();
    const auto consider = [&](const std::vector<Vec2>& candidates) {
        for (const Vec2& p : candidates) {
            const double d = (p - w).norm();
            if (d < bestDistance && clear(p)) {
                best = p;
                bestDistance = d;
            }
        }
    };

    // 1. The feet of the perpendiculars: often the answer (pushed straight out of one ball).
    std::vector<Vec2> candidates;
    for (const Circle& c : all.circles) projections(c, w, candidates);
    for (const Line& l : all.lines) projections(l, w, candidates);
    consider(candidates);

    // 2. Corners where two boundaries cross. A corner nearer than the best so far lies on two
    //    boundaries that both pass nearer than that, so only those need crossing.
    Boundaries near;
    for (const Circle& c : all.circles)
        if (distanceTo(c, w) <= bestDistance) near.circles.push_back(c);
    for (const Line& l : all.lines)
        if (distanceTo(l, w) <= bestDistance) near.lines.push_back(l);
    candidates.clear();
    for (std::size_t i = 0; i < near.circles.size(); ++i) {
        for (std::size_t j = i + 1; j < near.circles.size(); ++j) intersections(near.circles[i], near.circles[j], candidates);
        for (const Line& l : near.lines) intersections(near.circles[i], l, candidates);
    }
    for (std::size_t i = 0; i < near.lines.size(); ++i)
        for (std::size_t j = i + 1; j < near.lines.size(); ++j) intersections(near.lines[i], near.lines[j], candidates);
    consider(candidates);
    return best;
}

std::optional<Vec2> nearestLegalSpot(const Setup& setup, std::size_t index, const Vec2& wanted, double gap)
{
    if (index >= setup.balls.size() || !legal::tableSpecUsable(setup.table)) return std::nullopt;
    return nearestLegalSpot(makeTable(setup.table), setup.balls, setup.balls[index].radius, wanted, gap,
                            static_cast<int>(index));
}

}  // namespace cuelab
