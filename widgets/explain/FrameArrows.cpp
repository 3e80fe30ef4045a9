#include "FrameArrows.h"

#include "i18n/UiNumbers.h"

#include <QCoreApplication>

#include <algorithm>

namespace cuelab {

namespace {

// The context lupdate gives tr() calls in functions of namespace cuelab (resources/translations).
QString tr(const char* text) { return QCoreApplication::translate("cuelab", text); }

constexpr double kShortest = 1e-4;   // m: shorter arrows are not drawn
constexpr int kPathSamples = 40;     // per side of the event
const QColor kChangeColours[] = {QColor(150, 255, 80), QColor(255, 230, 60)};  // J (as EventArrows), −J
const QColor kFrameColour(255, 255, 255);
const QColor kFramePathColours[] = {QColor(195, 150, 255), QColor(255, 195, 215)};  // each ball's p colour

Vec3 lifted(const Vec2& v, double z) { return Vec3(v.x(), v.y(), z); }

}  // namespace

ViewLayer momentumChangeLayer(const explain::Explanation& e, ArrowFrame frame)
{
    ViewLayer layer;
    if (!isCollision(e.kind) || !e.hasContact || e.bodies.empty()) return layer;
    const double z = arrowPlaneHeight(e);
    for (std::size_t k = 0; k < e.bodies.size(); ++k) {
        const explain::Body& b = e.bodies[k];
        const Vec2 p = framedMomentum(e, k, 0, frame), q = framedMomentum(e, k, 1, frame);
        const Vec2 change = q - p;  // J on the first ball, −J on the second (the frame cancels out)
        if (kArrowMetresPerNewtonSecond * change.norm() < kShortest) continue;
        const Vec3 from = lifted(b.before.position + kArrowMetresPerNewtonSecond * p, z);
        const Vec3 to = lifted(b.before.position + kArrowMetresPerNewtonSecond * q, z);
        const QString id = QString::fromStdString(b.id);
        const QString value = uiNumber(change.norm(), 3);
        // Labelled halfway: its head is the tip of p′, whose own label stands there.
        layer.arrows.push_back({from, to, kChangeColours[k % 2], 2.5f,
                                k == 0 ? tr("Δp %1 = J = %2 N·s").arg(id, value) : tr("Δp %1 = −J = %2 N·s").arg(id, value),
                                0.5f});
    }
    return layer;
}

ViewLayer centreOfMassLayer(const SimulationResult& result, const explain::Explanation& e, double window)
{
    ViewLayer layer;
    if (e.kind != EventKind::BallBall || e.bodies.size() != 2) return layer;
    const double z = arrowPlaneHeight(e);
    const double m0 = e.bodies[0].mass, m1 = e.bodies[1].mass;
    const auto centre = [&](const Vec2& a, const Vec2& b) { return Vec2((m0 * a + m1 * b) / (m0 + m1)); };
    const Vec2 here = centre(e.bodies[0].before.position, e.bodies[1].before.position);
    LayerMarker& marker = layer.markers.emplace_back();
    marker.position = lifted(here, z);
    marker.colour = kFrameColour;
    marker.size = 10.0f;
    marker.label = tr("centre of mass");
    std::vector<aim::FrameBody> bodies;
    for (const explain::Body& b : e.bodies) bodies.push_back({b.mass, b.before.velocity, b.after.velocity});
    const Vec2 V = aim::centreOfMassFrame(bodies).velocity;
    if (V.norm() * 0.3 >= kShortest)
        layer.arrows.push_back({lifted(here, z), lifted(here + 0.3 * V, z), kFrameColour, 2.0f,
                                tr("V = %1 m/s").arg(uiNumber(V.norm(), 3))});
    // The paths near the event in the frame: each side sampled from the exact motion.
    const double from = std::max(0.0, e.time - window), to = std::min(result.endTime, e.time + window);
    for (std::size_t k = 0; k < 2; ++k) {
        LayerPolyline& path = layer.polylines.emplace_back();
        path.colour = kFramePathColours[k];
        path.width = 2.0f;
        for (int s = 0; s <= 2 * kPathSamples; ++s) {
            const double t = s <= kPathSamples ? from + (e.time - from) * s / kPathSamples
                                               : e.time + (to - e.time) * (s - kPathSamples) / kPathSamples;
            const BallState a = result.stateAt(e.bodies[0].ball, t), b = result.stateAt(e.bodies[1].ball, t);
            if (a.motion == MotionState::Pocketed || b.motion == MotionState::Pocketed) continue;
            const Vec2 own = k == 0 ? a.position : b.position;
            path.points.push_back(lifted(own - centre(a.position, b.position) + here, z));
        }
        path.label = tr("%1, seen from the centre of mass").arg(QString::fromStdString(e.bodies[k].id));
        if (path.points.size() < 2) layer.polylines.pop_back();
    }
    layer.legend = tr("Centre-of-mass frame: paths within %1 s of the event").arg(window);
    return layer;
}

}  // namespace cuelab
