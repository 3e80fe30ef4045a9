#include "LayerPass.h"

#include <QOpenGLShaderProgram>

#include <cmath>
#include <numbers>

namespace cuelab {

namespace {

constexpr float kPathLift = 0.002f;  // m above the cloth: a ghost path lies over the simulation's own

QVector3D at(const Vec3& p) { return QVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())); }

QVector4D rgba(const QColor& c) { return QVector4D(c.redF(), c.greenF(), c.blueF(), c.alphaF()); }

bool wellFormed(const GhostTrack& g)
{
    if (g.times.empty() || g.times.size() != g.positions.size()) return false;
    for (std::size_t k = 1; k < g.times.size(); ++k)
        if (!(g.times[k] >= g.times[k - 1])) return false;
    return true;
}

// Starts a run of `width` unless the last one has it already.
void beginRun(std::vector<LayerPass::Run>& runs, const std::vector<LineVertex>& lines, float width, bool dashed)
{
    if (!runs.empty() && runs.back().width == width && runs.back().dashedFuture == dashed) return;
    runs.push_back({width, static_cast<int>(lines.size()), 0, dashed});
}

void endRun(std::vector<LayerPass::Run>& runs, const std::vector<LineVertex>& lines)
{
    if (!runs.empty()) runs.back().count = static_cast<int>(lines.size()) - runs.back().first;
}

void segment(std::vector<LineVertex>& out, const QVector3D& a, const QVector3D& b, const QVector4D& colour)
{
    out.push_back({a, colour, -1.0f, 0.0f});
    out.push_back({b, colour, -1.0f, 0.0f});
}

}  // namespace

void LayerPass::create(unsigned int quadVbo)
{
    staticLines_.create();
    dynamicLines_.create();
    ghosts_.create(quadVbo);
    staticDirty_ = true;
}

void LayerPass::reset()
{
    staticLines_.reset();
    dynamicLines_.reset();
    ghosts_.reset();
    staticDirty_ = true;
}

void LayerPass::setLayers(const ViewLayers& layers)
{
    layers_ = layers;
    staticDirty_ = true;
}

bool LayerPass::empty() const
{
    for (const auto& [name, layer] : layers_)
        if (layer.visible && !layer.empty()) return false;
    return true;
}

void LayerPass::drawGhosts(const RenderFrame& frame)
{
    instances_.clear();
    const float identity[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    for (const auto& [name, layer] : layers_) {
        if (!layer.visible) continue;
        for (const GhostTrack& g : layer.ghosts) {
            Vec2 p;
            if (!ghostInScope(g, frame.pathScope, frame.selectedBall) || !ghostPositionAt(g, frame.time, &p)) continue;
            const auto r = static_cast<float>(g.radius);
            appendBallInstance(instances_, QVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()), r), r, identity,
                               QVector3D(g.colour.redF(), g.colour.greenF(), g.colour.blueF()), 0, false, false, false,
                               g.colour.alphaF());
        }
    }
    ghosts_.upload(instances_);
    ghosts_.draw();
}

void LayerPass::drawLines(QOpenGLShaderProgram& lineProgram, const RenderFrame& frame)
{
    if (frame.pathScope != shownScope_ || frame.selectedBall != shownSelected_) {
        shownScope_ = frame.pathScope;
        shownSelected_ = frame.selectedBall;
        staticDirty_ = true;
    }
    if (staticDirty_) {
        // Ghost paths (timed, for the past/future split) and polylines.
        scratch_.clear();
        staticRuns_.clear();
        for (const auto& [name, layer] : layers_) {
            if (!layer.visible) continue;
            for (const GhostTrack& g : layer.ghosts) {
                if (!g.showPath || !wellFormed(g) || g.positions.size() < 2 || !ghostInScope(g, frame.pathScope, frame.selectedBall))
                    continue;
                beginRun(staticRuns_, scratch_, 2.0f, true);
                QVector4D colour = rgba(g.colour);
                colour.setW(std::max(0.55f, colour.w()));  // a faint ghost still gets a visible path
                double travelled = 0.0;
                for (std::size_t k = 1; k < g.positions.size(); ++k) {
                    const Vec2 a = g.positions[k - 1], b = g.positions[k];
                    const QVector3D pa(static_cast<float>(a.x()), static_cast<float>(a.y()), kPathLift);
                    const QVector3D pb(static_cast<float>(b.x()), static_cast<float>(b.y()), kPathLift);
                    scratch_.push_back({pa, colour, static_cast<float>(g.times[k - 1]), static_cast<float>(travelled)});
                    travelled += (b - a).norm();
                    scratch_.push_back({pb, colour, static_cast<float>(g.times[k]), static_cast<float>(travelled)});
                }
                endRun(staticRuns_, scratch_);
            }
            for (const LayerPolyline& line : layer.polylines) {
                if (line.points.size() < 2) continue;
                beginRun(staticRuns_, scratch_, line.width, false);
                for (std::size_t k = 1; k < line.points.size(); ++k)
                    segment(scratch_, at(line.points[k - 1]), at(line.points[k]), rgba(line.colour));
                if (line.closed && line.points.size() > 2)
                    segment(scratch_, at(line.points.back()), at(line.points.front()), rgba(line.colour));
                endRun(staticRuns_, scratch_);
            }
        }
        staticLines_.upload(scratch_);
        staticDirty_ = false;
    }

    // Arrows with their heads in the plane of the shaft and the line of sight; markers facing the eye.
    scratch_.clear();
    dynamicRuns_.clear();
    for (const auto& [name, layer] : layers_) {
        if (!layer.visible) continue;
        for (const LayerArrow& a : layer.arrows) {
            const QVector3D from = at(a.from), to = at(a.to);
            const QVector3D shaft = to - from;
            const float length = shaft.length();
            if (!(length > 1e-6f)) continue;
            beginRun(dynamicRuns_, scratch_, a.width, false);
            const QVector3D dir = shaft / length;
            QVector3D side = QVector3D::crossProduct(dir, (to - frame.eye).normalized());
            if (side.lengthSquared() < 1e-8f) side = QVector3D::crossProduct(dir, frame.cameraUp);
            side.normalize();
            // The head grows with the width and the distance, within the arrow's length.
            const float pixel = frame.pixelAngle * (to - frame.eye).length();  // m per framebuffer pixel
            const float head = std::min(0.4f * length, (7.0f + 2.0f * a.width) * frame.devicePixelRatio * pixel);
            const QVector4D colour = rgba(a.colour);
            segment(scratch_, from, to - 0.3f * head * dir, colour);
            const QVector3D back = to - head * dir;
            segment(scratch_, to, back + 0.5f * head * side, colour);
            segment(scratch_, to, back - 0.5f * head * side, colour);
            segment(scratch_, back + 0.5f * head * side, back - 0.5f * head * side, colour);
            endRun(dynamicRuns_, scratch_);
        }
        for (const LayerMarker& m : layer.markers) {
            const QVector3D c = at(m.position);
            const QVector3D toEye = (frame.eye - c).normalized();
            QVector3D right = QVector3D::crossProduct(frame.cameraUp, toEye);
            if (right.lengthSquared() < 1e-8f) right = QVector3D(1, 0, 0);
            right.normalize();
            const QVector3D up = QVector3D::crossProduct(toEye, right);
            const float radius = 0.5f * m.size * frame.devicePixelRatio * frame.pixelAngle * (frame.eye - c).length();
            beginRun(dynamicRuns_, scratch_, 2.0f, false);
            const QVector4D colour = rgba(m.colour);
            constexpr int kSteps = 16;
            for (int k = 0; k < kSteps; ++k) {
                const double a0 = 2.0 * std::numbers::pi * k / kSteps, a1 = 2.0 * std::numbers::pi * (k + 1) / kSteps;
                segment(scratch_, c + radius * (static_cast<float>(std::cos(a0)) * right + static_cast<float>(std::sin(a0)) * up),
                        c + radius * (static_cast<float>(std::cos(a1)) * right + static_cast<float>(std::sin(a1)) * up), colour);
            }
            segment(scratch_, c - 0.55f * radius * right, c + 0.55f * radius * right, colour);
            segment(scratch_, c - 0.55f * radius * up, c + 0.55f * radius * up, colour);
            endRun(dynamicRuns_, scratch_);
        }
    }
    dynamicLines_.upload(scratch_);

    for (const Run& run : staticRuns_)
        staticLines_.draw(lineProgram, run.width * frame.devicePixelRatio, 1.0f, run.dashedFuture ? 0.6f : 1.0f,
                          run.dashedFuture ? 0.035f : 0.0f, run.first, run.count);
    for (const Run& run : dynamicRuns_)
        dynamicLines_.draw(lineProgram, run.width * frame.devicePixelRatio, 1.0f, 1.0f, 0.0f, run.first, run.count);
}

}  // namespace cuelab
