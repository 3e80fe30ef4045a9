#include "TableView.h"

#include "BallPlacement.h"
#include "OverlayLabels.h"
#include "SceneFraming.h"
#include "TableRenderer.h"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QSurfaceFormat>
#include <QWheelEvent>
#include <QtMath>

#include <cmath>

namespace cuelab {

namespace {

constexpr float kOrbitDegPerPixel = 0.3f;    // degrees of orbit per pixel of mouse travel
constexpr float kPresetTransitionS = 0.6f;   // s
constexpr double kDragThresholdPx = 3.0;     // pixels before a press becomes a drag
constexpr int kFpsReportIntervalMs = 500;  // ms between reports while animating
constexpr int kIdleGapMs = 500;            // ms: frames further apart do not make an animation
constexpr int kSettleMs = 100;             // ms after the camera stops before the antialiased frame

}  // namespace

TableView::TableView(QWidget* parent) : QOpenGLWidget(parent)
{
    // OpenGL 3.3 core whatever the application's default, and single-sampled: the balls and lines
    // antialias themselves in their shaders and the renderer multisamples the table once into its
    // cache, so a multisampled widget would only make a software rasteriser shade, copy and resolve
    // four samples of every pixel every frame.
    QSurfaceFormat f = QSurfaceFormat::defaultFormat();
    f.setVersion(3, 3);
    f.setProfile(QSurfaceFormat::CoreProfile);
    f.setSamples(0);
    f.setDepthBufferSize(std::max(24, f.depthBufferSize()));
    setFormat(f);
    overlays_ = defaultOverlays();
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(200, 120);
    cameraTimer_.setInterval(16);
    connect(&cameraTimer_, &QTimer::timeout, this, &TableView::stepCameraAnimation);
    settleTimer_.setSingleShot(true);
    settleTimer_.setInterval(kSettleMs);
    connect(&settleTimer_, &QTimer::timeout, this, qOverload<>(&QWidget::update));
    idleTimer_.setSingleShot(true);
    idleTimer_.setInterval(kIdleGapMs);
    connect(&idleTimer_, &QTimer::timeout, this, &TableView::animationStopped);
}

TableView::~TableView() { releaseGl(); }

void TableView::setScene(ViewScene scene)
{
    const bool tableChanged = !scene_.result || !scene.result || scene_.result->table.kind != scene.result->table.kind ||
                              scene_.result->table.length != scene.result->table.length ||
                              scene_.result->table.width != scene.result->table.width;
    scene_ = std::move(scene);
    if (renderer_) renderer_->setScene(scene_);
    const double end = scene_.result ? scene_.result->endTime : 0.0;
    time_ = std::clamp(time_, 0.0, std::max(end, 0.0));
    if (selectedBall_ >= 0 && (!scene_.result || static_cast<std::size_t>(selectedBall_) >= scene_.result->balls.size()))
        selectedBall_ = -1;
    if (cameraAutomatic_ && tableChanged) camera_.setPose(OrbitCamera::presetPose(CameraPreset::Top, presetFrameFor(scene_, aspect())));
    update();
}

void TableView::setTime(double seconds)
{
    const double end = scene_.result ? std::max(scene_.result->endTime, 0.0) : 0.0;
    const double t = std::clamp(seconds, 0.0, end);
    if (t == time_) return;
    time_ = t;
    update();
}

void TableView::setSelectedBall(int index)
{
    if (index == selectedBall_) return;
    selectedBall_ = index;
    update();
}

void TableView::setHighlightedEvent(int index)
{
    if (index == highlightedEvent_) return;
    highlightedEvent_ = index;
    update();
}

void TableView::setOverlayVisible(Overlay overlay, bool visible)
{
    if (overlayVisible(overlay) == visible) return;
    overlays_.set(static_cast<std::size_t>(overlay), visible);
    update();
}

bool TableView::overlayVisible(Overlay overlay) const { return overlays_.test(static_cast<std::size_t>(overlay)); }

void TableView::setCameraPreset(CameraPreset preset, bool animated)
{
    cameraAutomatic_ = preset == CameraPreset::Top && !animated;
    const CameraPose to = OrbitCamera::presetPose(preset, presetFrameFor(scene_, aspect()));
    if (animated) {
        camera_.transitionTo(to, kPresetTransitionS);
        cameraClock_.start();
        cameraTimer_.start();
    } else {
        camera_.setPose(to);
    }
    update();
}

void TableView::stepCameraAnimation()
{
    const float dt = static_cast<float>(cameraClock_.restart()) / 1000.0f;
    if (!camera_.advance(dt)) cameraTimer_.stop();
    update();
}

int TableView::pickBall(const QPointF& widgetPos) const
{
    if (!scene_.result) return -1;
    const SimulationResult& r = *scene_.result;
    const Ray ray = camera_.ray(toNdc(widgetPos), aspect());
    const Vec3 o(ray.origin.x(), ray.origin.y(), ray.origin.z());
    const Vec3 d(ray.direction.x(), ray.direction.y(), ray.direction.z());
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < r.balls.size(); ++i) {
        const BallState s = r.timelines.empty() ? r.balls[i].state : r.stateAt(static_cast<int>(i), time_);
        if (s.motion == MotionState::Pocketed) continue;
        const double radius = r.balls[i].radius;
        // |o + t d - c|^2 = R^2 with |d| = 1: t = b -+ sqrt(b^2 - |o - c|^2 + R^2), b = (c - o).d
        const Vec3 c(s.position.x(), s.position.y(), radius);
        const Vec3 oc = c - o;
        const double b = oc.dot(d);
        const double disc = b * b - oc.squaredNorm() + radius * radius;
        if (disc < 0.0) continue;
        const double t = b - std::sqrt(disc);
        if (t > 0.0 && t < bestDistance) {
            bestDistance = t;
            best = static_cast<int>(i);
        }
    }
    return best;
}

std::optional<QVector3D> TableView::clothPointUnder(const QPointF& widgetPos, float height) const
{
    const Ray ray = camera_.ray(toNdc(widgetPos), aspect());
    if (std::abs(ray.direction.z()) < 1e-6f) return std::nullopt;
    const float t = (height - ray.origin.z()) / ray.direction.z();
    if (t <= 0.0f) return std::nullopt;
    return ray.origin + t * ray.direction;
}

void TableView::initializeGL()
{
    initializeOpenGLFunctions();
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &TableView::releaseGl, Qt::DirectConnection);
    renderer_ = std::make_unique<TableRenderer>();
    QString error;
    if (!renderer_->initialize(&error)) {
        qWarning("TableView: %s", qPrintable(error));
        renderer_->release();
        renderer_.reset();
        return;
    }
    renderer_->setScene(scene_);
}

void TableView::releaseGl()
{
    if (!renderer_) return;
    makeCurrent();
    renderer_->release();
    renderer_.reset();
    doneCurrent();
}

void TableView::resizeGL(int, int)
{
    if (cameraAutomatic_) camera_.setPose(OrbitCamera::presetPose(CameraPreset::Top, presetFrameFor(scene_, aspect())));
}

void TableView::paintGL()
{
    if (!renderer_) {
        glClearColor(0.11f, 0.12f, 0.14f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        return;
    }
    RenderFrame frame;
    frame.viewProjection = camera_.projection(aspect()) * camera_.viewMatrix();
    frame.eye = camera_.eye();
    frame.cameraUp = camera_.up();
    frame.viewportPixels = size() * devicePixelRatio();
    frame.pixelAngle = pixelAngle(frame.viewportPixels.height());
    frame.time = time_;
    frame.overlays = overlays_;
    frame.selectedBall = selectedBall_;
    frame.highlightedEvent = highlightedEvent_;
    renderer_->render(frame);
    // While the camera moves the table is drawn without its antialiased cache; once it has been still
    // for kSettleMs, one more frame draws it antialiased.
    if (renderer_->tableUncached()) settleTimer_.start();
    lastGlError_ = glGetError();
    while (glGetError() != GL_NO_ERROR) {
    }

    QPainter painter(this);
    paintOverlayLabels(painter, scene_, LabelFrame{frame.viewProjection, size(), time_, overlays_, highlightedEvent_});
    painter.end();
    countFrame();
}

// A frame drawn within kIdleGapMs of the previous one continues a run of animation; the rate counts
// only the intervals between the frames of a run, never the idle time before it.
void TableView::countFrame()
{
    if (!idleTimer_.isActive() || !fpsClock_.isValid()) {
        fpsClock_.start();
        framesSinceReport_ = 0;
    } else {
        ++framesSinceReport_;
        const qint64 elapsedMs = fpsClock_.elapsed();
        if (elapsedMs >= kFpsReportIntervalMs) {
            emit framesPerSecond(1000.0 * framesSinceReport_ / static_cast<double>(elapsedMs));
            rateReported_ = true;
            framesSinceReport_ = 0;
            fpsClock_.restart();
        }
    }
    idleTimer_.start();
}

void TableView::animationStopped()
{
    fpsClock_.invalidate();
    if (!rateReported_) return;
    rateReported_ = false;
    emit framesPerSecond(0.0);
}

void TableView::mousePressEvent(QMouseEvent* event)
{
    pressPos_ = lastPos_ = event->position();
    dragMoved_ = false;
    dragBall_ = -1;
    dragGrabOffset_.reset();
    const bool panButton = event->button() == Qt::RightButton || event->button() == Qt::MiddleButton ||
                           (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier));
    if (panButton) {
        dragMode_ = DragMode::Pan;
        return;
    }
    if (event->button() != Qt::LeftButton) return;
    const int ball = pickBall(event->position());
    if (ball >= 0) {
        emit ballClicked(ball);
        // Balls move only where they are set up: at t = 0. Later a press on a ball selects it and
        // a drag orbits.
        if (time_ <= 0.0 && scene_.result) {
            dragMode_ = DragMode::Ball;
            dragBall_ = ball;
            const auto r = static_cast<float>(scene_.result->balls[static_cast<std::size_t>(ball)].radius);
            const Vec2 c = scene_.result->balls[static_cast<std::size_t>(ball)].state.position;
            if (const std::optional<QVector3D> p = clothPointUnder(event->position(), r))
                dragGrabOffset_ = *p - QVector3D(static_cast<float>(c.x()), static_cast<float>(c.y()), r);
            return;
        }
    }
    dragMode_ = DragMode::Orbit;
}

void TableView::mouseMoveEvent(QMouseEvent* event)
{
    const QPointF pos = event->position();
    if (!dragMoved_ && QLineF(pos, pressPos_).length() < kDragThresholdPx) return;
    dragMoved_ = true;
    switch (dragMode_) {
    case DragMode::None: break;
    case DragMode::Orbit:
        cameraAutomatic_ = false;
        camera_.orbit(-kOrbitDegPerPixel * static_cast<float>(pos.x() - lastPos_.x()),
                      kOrbitDegPerPixel * static_cast<float>(pos.y() - lastPos_.y()));
        update();
        break;
    case DragMode::Pan:
        cameraAutomatic_ = false;
        camera_.pan(toNdc(lastPos_), toNdc(pos), aspect());
        update();
        break;
    case DragMode::Ball: {
        if (!scene_.result || dragBall_ < 0 || static_cast<std::size_t>(dragBall_) >= scene_.result->balls.size()) break;
        const auto r = static_cast<float>(scene_.result->balls[static_cast<std::size_t>(dragBall_)].radius);
        const std::optional<QVector3D> p = clothPointUnder(pos, r);
        if (!p) break;
        const QVector3D centre = *p - dragGrabOffset_.value_or(QVector3D());
        if (const std::optional<Vec2> placed =
                constrainedPlacement(*scene_.result, dragBall_, Vec2(centre.x(), centre.y())))
            emit ballDragged(dragBall_, placed->x(), placed->y());
        break;
    }
    }
    lastPos_ = pos;
}

void TableView::mouseReleaseEvent(QMouseEvent* event)
{
    if (dragMode_ == DragMode::Ball && dragMoved_) emit ballDragFinished(dragBall_);
    if (dragMode_ == DragMode::Orbit && !dragMoved_ && event->button() == Qt::LeftButton && pickBall(event->position()) < 0)
        emit ballClicked(-1);
    dragMode_ = DragMode::None;
    dragBall_ = -1;
}

void TableView::mouseDoubleClickEvent(QMouseEvent* event)
{
    // Centre on what was double-clicked: a ball, or the cloth.
    std::optional<QVector3D> point;
    const int ball = pickBall(event->position());
    if (ball >= 0 && scene_.result) {
        const BallState s = scene_.result->stateAt(ball, time_);
        point = QVector3D(static_cast<float>(s.position.x()), static_cast<float>(s.position.y()), 0.0f);
    } else {
        point = clothPointUnder(event->position(), 0.0f);
    }
    if (!point) return;
    cameraAutomatic_ = false;
    CameraPose to = camera_.pose();
    to.target = *point;
    camera_.transitionTo(to, 0.35f);
    cameraClock_.start();
    cameraTimer_.start();
}

void TableView::wheelEvent(QWheelEvent* event)
{
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0.0) return;
    cameraAutomatic_ = false;
    const float factor = static_cast<float>(std::pow(0.88, steps));
    const QVector3D point = clothPointUnder(event->position(), 0.0f).value_or(camera_.target());
    camera_.zoomTowards(point, factor);
    update();
    event->accept();
}

float TableView::aspect() const
{
    return height() > 0 && width() > 0 ? static_cast<float>(width()) / static_cast<float>(height()) : 1.6f;
}

QPointF TableView::toNdc(const QPointF& p) const
{
    return QPointF(2.0 * p.x() / std::max(1, width()) - 1.0, 1.0 - 2.0 * p.y() / std::max(1, height()));
}

}  // namespace cuelab
