#include "SetupGeometry.h"

#include <algorithm>
#include <cmath>

namespace cuelab::io {

namespace {

QString ballPath(std::size_t index, const char* key)
{
    return QStringLiteral("balls[%1].%2").arg(index).arg(QLatin1String(key));
}

QString quoted(const std::string& id) { return QLatin1Char('"') + QString::fromStdString(id) + QLatin1Char('"'); }

// Distance from p to the closest point of the segment [a, b].
double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b)
{
    const Vec2 ab = b - a;
    const double lengthSquared = ab.squaredNorm();
    const double t = lengthSquared > 0.0 ? std::clamp((p - a).dot(ab) / lengthSquared, 0.0, 1.0) : 0.0;
    const Vec2 closest = a + t * ab;
    return (p - closest).norm();
}

// A pocketed table needs every rail nose to keep a positive length between its two pocket mouths;
// a table too short or too narrow for its pockets turns a rail inside out.
std::optional<SetupProblem> checkRails(const Table& table)
{
    for (const CushionSegment& c : table.cushions) {
        if (c.id.rfind("rail-", 0) != 0) continue;
        const Vec2 along = c.b - c.a;
        // Rails run so that their inward normal is on the left: cross(along, normal) > 0.
        if (along.x() * c.normal.y() - along.y() * c.normal.x() > 0.0) continue;
        const bool alongLength = std::abs(c.normal.y()) > 0.5;
        return SetupProblem{alongLength ? QStringLiteral("table.length") : QStringLiteral("table.width"),
                            QStringLiteral("the table is too %1 for its pockets: rail %2 has no length left")
                                .arg(alongLength ? QStringLiteral("short") : QStringLiteral("narrow"),
                                     quoted(c.id))};
    }
    return std::nullopt;
}

std::optional<SetupProblem> checkBallOnTable(const Table& table, const Ball& ball, std::size_t index)
{
    const Vec2& p = ball.state.position;
    const double r = ball.radius;
    if (table.cushionHeight >= 2.0 * r)
        return SetupProblem{ballPath(index, "radius"),
                            QStringLiteral("a ball of radius %1 m is lower than the cushion nose (%2 m above the cloth)")
                                .arg(r)
                                .arg(table.cushionHeight)};
    if (p.x() < 0.0 || p.x() > table.length || p.y() < 0.0 || p.y() > table.width)
        return SetupProblem{ballPath(index, "position"),
                            QStringLiteral("outside the playing surface (0 to %1 m by 0 to %2 m)")
                                .arg(table.length)
                                .arg(table.width)};
    for (const Pocket& pocket : table.pockets)
        if ((p - pocket.centre).norm() < pocket.radius)
            return SetupProblem{ballPath(index, "position"), QStringLiteral("lies in pocket %1").arg(quoted(pocket.id))};

    // The deepest overlap with a cushion nose or a jaw tip, if any exceeds the tolerance.
    double deepest = kOverlapTolerance;
    QString culprit;
    for (const CushionSegment& c : table.cushions) {
        const double overlap = r - distanceToSegment(p, c.a, c.b);
        if (overlap > deepest) {
            deepest = overlap;
            culprit = QStringLiteral("cushion ") + quoted(c.id);
        }
    }
    for (const JawTip& jaw : table.jaws) {
        const double overlap = r + jaw.radius - (p - jaw.centre).norm();
        if (overlap > deepest) {
            deepest = overlap;
            culprit = QStringLiteral("jaw ") + quoted(jaw.id);
        }
    }
    if (!culprit.isEmpty())
        return SetupProblem{ballPath(index, "position"),
                            QStringLiteral("overlaps %1 by %2").arg(culprit, describeLength(deepest))};
    return std::nullopt;
}

}  // namespace

QString describeLength(double metres)
{
    const double magnitude = std::abs(metres);
    if (magnitude >= 0.1) return QString::number(metres, 'f', 3) + QStringLiteral(" m");
    if (magnitude >= 1e-4) return QString::number(metres * 1e3, 'f', 1) + QStringLiteral(" mm");
    if (magnitude >= 1e-7) return QString::number(metres * 1e6, 'f', 1) + QStringLiteral(" µm");
    return QString::number(metres * 1e9, 'f', 1) + QStringLiteral(" nm");
}

std::optional<SetupProblem> checkGeometry(const Setup& setup, const Table& table)
{
    if (auto problem = checkRails(table)) return problem;
    for (std::size_t i = 0; i < setup.balls.size(); ++i) {
        const Ball& ball = setup.balls[i];
        if (auto problem = checkBallOnTable(table, ball, i)) return problem;
        for (std::size_t j = 0; j < i; ++j) {
            const Ball& other = setup.balls[j];
            const double overlap = ball.radius + other.radius - (ball.state.position - other.state.position).norm();
            if (overlap > kOverlapTolerance)
                return SetupProblem{ballPath(i, "position"),
                                    QStringLiteral("overlaps ball %1 by %2").arg(quoted(other.id), describeLength(overlap))};
        }
    }
    return std::nullopt;
}

}  // namespace cuelab::io
