#include "TableRenderer.h"

#include "CuePlacement.h"
#include "OrbitCamera.h"

#include <QOpenGLShaderProgram>

#include <cmath>
#include <numbers>

namespace cuelab {

float pixelAngle(int heightPixels)
{
    const float halfFov = OrbitCamera::kFieldOfViewDeg / 2.0f * std::numbers::pi_v<float> / 180.0f;
    return 2.0f * std::tan(halfFov) / static_cast<float>(std::max(1, heightPixels));
}

TableRenderer::TableRenderer() = default;
TableRenderer::~TableRenderer() = default;

bool TableRenderer::initialize(QString* error)
{
    if (!currentGl()) {
        if (error) *error = QStringLiteral("No OpenGL context is current.");
        return false;
    }
    if (!shaders_.build(error)) return false;
    table_.create();
    balls_.create();
    overlays_.create(balls_.quadBuffer());
    layers_.create(balls_.quadBuffer());
    if (scene_.result) table_.setTable(scene_.result->table);
    initialized_ = true;
    return true;
}

void TableRenderer::release()
{
    layers_.reset();
    overlays_.reset();
    balls_.reset();
    table_.reset();
    shaders_.reset();
    initialized_ = false;
}

void TableRenderer::setScene(const ViewScene& scene)
{
    scene_ = scene;
    if (scene_.result) table_.setTable(scene_.result->table);
    balls_.setScene(scene_);
    overlays_.setScene(scene_);
}

void TableRenderer::setSetupBalls(const std::vector<Ball>& balls) { setupBalls_ = balls; }

std::optional<QMatrix4x4> TableRenderer::cueModel(const RenderFrame& frame) const
{
    if (frame.time > 0.0 || !scene_.shot || !frame.overlays.test(static_cast<std::size_t>(Overlay::CueAndAim)))
        return std::nullopt;
    const SimulationResult& r = *scene_.result;
    const std::vector<Ball>& balls = setupBalls_.size() == r.balls.size() ? setupBalls_ : r.balls;
    const std::optional<CuePose> pose = cuePose(r, balls, *scene_.shot);
    if (!pose) return std::nullopt;
    return pose->model;
}

void TableRenderer::render(const RenderFrame& frame)
{
    QOpenGLExtraFunctions* gl = currentGl();
    if (!gl) return;
    gl->glViewport(0, 0, frame.viewportPixels.width(), frame.viewportPixels.height());
    gl->glClearColor(0.11f, 0.12f, 0.14f, 1.0f);
    gl->glDisable(GL_SCISSOR_TEST);  // QPainter may leave it on in a widget
    gl->glDisable(GL_STENCIL_TEST);
    tableUncached_ = false;
    if (!initialized_ || !scene_.result) {
        gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        return;
    }
    const std::array<QVector3D, 2> lamps = lampPositions(scene_.result->table);
    balls_.update(frame);

    // The table (and the cue before the shot), from the cache when the camera has not moved.
    gl->glEnable(GL_DEPTH_TEST);
    gl->glDepthFunc(GL_LESS);
    gl->glDepthMask(GL_TRUE);
    gl->glDisable(GL_BLEND);
    gl->glDisable(GL_CULL_FACE);
    GLint target = 0;
    gl->glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    tableUncached_ = table_.draw(frame, shaders_, cueModel(frame), static_cast<GLuint>(target));

    // Contact shadows (blended, no depth writes), then the balls (blending only their antialiased rim,
    // writing depth).
    gl->glEnable(GL_BLEND);
    // Colour blended over what is there; the frame's alpha kept opaque (a translucent ghost must not
    // leave a see-through hole in a screenshot).
    gl->glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    gl->glDepthMask(GL_FALSE);
    balls_.drawShadows(frame, shaders_);
    gl->glDepthMask(GL_TRUE);
    balls_.drawBalls(frame, shaders_, lamps);

    // Overlays, then the layers: translucent, depth-tested against the table and the balls, not
    // writing depth.
    gl->glDepthMask(GL_FALSE);
    bindBallProgram(*shaders_.ghost, frame, lamps);
    overlays_.drawGhostBalls(frame);
    if (!layers_.empty()) layers_.drawGhosts(frame);
    bindLineProgram(*shaders_.line, frame);
    overlays_.drawLines(*shaders_.line, frame, balls_.states(), velocityDrag_);
    if (!layers_.empty()) layers_.drawLines(*shaders_.line, frame);

    gl->glBindVertexArray(0);
    gl->glDepthMask(GL_TRUE);
    gl->glDisable(GL_BLEND);
}

}  // namespace cuelab
