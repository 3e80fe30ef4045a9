#include "AimLayer.h"

#include "i18n/UiNumbers.h"

#include "Aim.h"
#include "Quantities.h"

#include <QCoreApplication>

namespace cuelab {

namespace {
QString tr(const char* text) { return QCoreApplication::translate("cuelab", text); }

constexpr double kLineLift = 0.003;    // m above the cloth: over the paths (2 mm), under the balls' tops
constexpr double kMarkerLift = 0.004;  // m above the ball's top, like the collision arrows
const QColor kGhost(255, 255, 255, 80);
const QColor kAimLine(255, 160, 40);     // orange, as EventArrows.h reserves for the aim line
const QColor kCentresLine(255, 70, 70);  // red: the ghost-ball construction's normal
}  // namespace

ViewLayer aimLayer(const SimulationResult& result)
{
    ViewLayer layer;
    int object = -1;
    const std::optional<aim::AimGeometry> g = aim::firstContact(result, nullptr, &object);
    if (!g || object < 0) return layer;
    const Ball& struck = result.balls.at(static_cast<std::size_t>(result.events.front().balls[0]));
    const Ball& other = result.balls.at(static_cast<std::size_t>(object));
    GhostTrack& ghost = layer.ghosts.emplace_back();
    ghost.label = tr("ghost ball");
    ghost.radius = struck.radius;
    ghost.colour = kGhost;
    ghost.times = {0.0, std::max(result.endTime, 1e-9)};
    ghost.positions = {g->ghostBall, g->ghostBall};
    ghost.showPath = false;
    // The aim line: from the ball's place through the ghost ball, on by one ball's width.
    const Vec2 beyond = g->ghostBall + 2.0 * struck.radius * g->path;
    layer.polylines.push_back({{Vec3(g->aimStart.x(), g->aimStart.y(), kLineLift), Vec3(beyond.x(), beyond.y(), kLineLift)},
                               kAimLine, 2.0f, false, tr("aim line")});
    const QString side = g->side == aim::CutSide::Left ? tr("left") : g->side == aim::CutSide::Right ? tr("right") : QString();
    const Vec2 on = g->objectBall + 3.0 * other.radius * g->lineOfCentres;
    layer.polylines.push_back({{Vec3(g->ghostBall.x(), g->ghostBall.y(), kLineLift), Vec3(on.x(), on.y(), kLineLift)},
                               kCentresLine, 2.0f, false,
                               tr("cut %1 %2, ball fraction %3")
                                   .arg(uiNumber(g->cutAngleDeg, 1) + QStringLiteral("°"), side,
                                        uiNumber(g->ballFraction, 2))
                                   .simplified()});
    LayerMarker& contact = layer.markers.emplace_back();
    contact.position = Vec3(g->contactPoint.x(), g->contactPoint.y(), 2.0 * std::max(struck.radius, other.radius) + kMarkerLift);
    contact.colour = kCentresLine;
    contact.size = 10.0f;
    return layer;
}

}  // namespace cuelab
