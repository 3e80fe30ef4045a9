#include "LegalGeometry.h"

#include "BallContact.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cuelab::legal {

double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b)
{
    const Vec2 ab = b - a;
    const double lengthSquared = ab.squaredNorm();
    const double t = lengthSquared > 0.0 ? std::clamp((p - a).dot(ab) / lengthSquared, 0.0, 1.0) : 0.0;
    const Vec2 closest = a + t * ab;
    return (p - closest).norm();
}

std::string ballPath(int index, const char* key)
{
    return "balls[" + std::to_string(index) + "]." + key;
}

std::string quoted(const std::string& text) { return '"' + text + '"'; }

bool tableSpecUsable(const TableSpec& spec)
{
    const auto usable = [](const std::optional<double>& x, double max) {
        return !x || (std::isfinite(*x) && *x > 0.0 && *x <= max);
    };
    return usable(spec.length, SetupBounds::tableSize) && usable(spec.width, SetupBounds::tableSize)
           && usable(spec.cushionHeight, SetupBounds::cushionHeight);
}

TableMargins tableMargins(const Table& table, double radius, const Vec2& p)
{
    constexpr double kFar = std::numeric_limits<double>::infinity();
    TableMargins m;
    m.surface = std::min({p.x(), table.length - p.x(), p.y(), table.width - p.y()});
    m.pocket = kFar;
    for (const Pocket& pocket : table.pockets) {
        const double margin = (p - pocket.centre).norm() - pocket.radius;
        if (margin < m.pocket) {
            m.pocket = margin;
            m.pocketId = pocket.id;
        }
    }
    m.contact = kFar;
    for (const CushionSegment& c : table.cushions) {
        const double gap = distanceToSegment(p, c.a, c.b) - radius;
        if (gap < m.contact) {
            m.contact = gap;
            m.contactId = "cushion " + quoted(c.id);
        }
    }
    for (const JawTip& jaw : table.jaws) {
        const double gap = (p - jaw.centre).norm() - radius - jaw.radius;
        if (gap < m.contact) {
            m.contact = gap;
            m.contactId = "jaw " + quoted(jaw.id);
        }
    }
    return m;
}

std::optional<SetupProblem> railsProblem(const Table& table)
{
    for (const CushionSegment& c : table.cushions) {
        if (c.id.rfind("rail-", 0) != 0) continue;
        const Vec2 along = c.b - c.a;
        // Rails run so that their inward normal is on the left: cross(along, normal) > 0.
        if (along.x() * c.normal.y() - along.y() * c.normal.x() > 0.0) continue;
        const bool alongLength = std::abs(c.normal.y()) > 0.5;
        return SetupProblem{alongLength ? "table.length" : "table.width", {}, -1,
                            std::string("the table is too ") + (alongLength ? "short" : "narrow") +
                                " for its pockets: rail " + quoted(c.id) + " has no length left"};
    }
    return std::nullopt;
}

std::optional<SetupProblem> tableProblem(const Table& table, const Ball& ball, int index)
{
    const std::string who = "ball " + quoted(ball.id);
    const Vec2& p = ball.state.position;
    if (table.cushionHeight >= 2.0 * ball.radius)
        return SetupProblem{ballPath(index, "radius"), ball.id, index,
                            who + " (radius " + describeNumber(ball.radius) +
                                " m) is lower than the cushion nose (" + describeNumber(table.cushionHeight) +
                                " m above the cloth)"};
    const TableMargins m = tableMargins(table, ball.radius, p);
    if (m.surface < 0.0)
        return SetupProblem{ballPath(index, "position"), ball.id, index,
                            who + " is outside the playing surface (0 to " + describeNumber(table.length) +
                                " m by 0 to " + describeNumber(table.width) + " m)"};
    if (m.pocket < 0.0)
        return SetupProblem{ballPath(index, "position"), ball.id, index,
                            who + " lies in pocket " + quoted(m.pocketId)};
    if (-m.contact > kOverlapTolerance)
        return SetupProblem{ballPath(index, "position"), ball.id, index,
                            who + " overlaps " + m.contactId + " by " + describeLength(-m.contact)};
    return std::nullopt;
}

std::optional<SetupProblem> overlapProblem(const Ball& ball, int index, const Ball& other)
{
    // Balls of unequal radius touch at the horizontal distance touchDistance (their centres are at
    // different heights). A ball given a height (z, CONTRACT.md "Airborne balls") is apart from another
    // in space: its centre is R + z above the cloth, so a ball may rest on another's shoulder.
    double overlap = touchDistance(ball.radius, other.radius) - (ball.state.position - other.state.position).norm();
    if (ball.state.z > 0.0 || other.state.z > 0.0) {
        const Vec2 d = ball.state.position - other.state.position;
        const double dz = (ball.radius + ball.state.z) - (other.radius + other.state.z);
        overlap = (ball.radius + other.radius) - std::sqrt(d.squaredNorm() + dz * dz);
    }
    if (!(overlap > kOverlapTolerance)) return std::nullopt;
    return SetupProblem{ballPath(index, "position"), ball.id, index,
                        "ball " + quoted(ball.id) + " overlaps ball " + quoted(other.id) + " by " +
                            describeLength(overlap)};
}

}  // namespace cuelab::legal
