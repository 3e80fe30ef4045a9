#include "TableView.h"

#include "AimDrag.h"
#include "CameraAnimator.h"
#include "FrameRateMeter.h"
#include "OverlayLabels.h"
#include "SceneFraming.h"
#include "TableInteraction.h"
#include "TableRenderer.h"

#include <QHelpEvent>
#include <QKeyEvent>
#include <QLineF>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QSurfaceFormat>
#include <QToolTip>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace cuelab {

namespace {

constexpr float kPresetTransitionS = 0.6f;  // s
constexpr int kSettleMs = 100;              // ms after the camera stops before the antialiased frame

bool sameTable(const ViewScene& a, const ViewScene& b)
{
    return a.result && b.result && a.result->table.kind == b.result->table.kind &&
           a.result->table.length == b.result->table.length && a.result->table.width == b.result->table.width;
}

}  // namespace

TableView::TableView(QWidget* parent)
    : QOpenGLWidget(parent), aim_(std::make_unique<AimDrag>(*this)), interaction_(std::make_unique<TableInteraction>(*this)),
      animator_(new CameraAnimator(camera_, this)), meter_(new FrameRateMeter(this))
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
    setMouseTracking(true);  // the cursor's shape and the highlight say what a press would drag
    setMinimumSize(200, 120);
    connect(animator_, &CameraAnimator::stepped, this, qOverload<>(&QWidget::update));
    connect(meter_, &FrameRateMeter::framesPerSecond, this, &TableView::framesPerSecond);
    settleTimer_.setSingleShot(true);
    settleTimer_.setInterval(kSettleMs);
    connect(&settleTimer_, &QTimer::timeout, this, qOverload<>(&QWidget::update));
}

TableView::~TableView() { releaseGl(); }

void TableView::setScene(ViewScene scene)
{
    const bool tableChanged = !sameTable(scene_, scene);
    scene_ = std::move(scene);
    if (renderer_) renderer_->setScene(scene_);
    const double end = scene_.result ? scene_.result->endTime : 0.0;
    time_ = std::clamp(time_, 0.0, std::max(end, 0.0));
    if (selectedBall_ >= 0 && (!scene_.result || static_cast<std::size_t>(selectedBall_) >= scene_.result->balls.size()))
        selectedBall_ = -1;
    if (scene_.result && setupBalls_.size() != scene_.result->balls.size()) setupBalls_.clear();
    if (renderer_) renderer_->setSetupBalls(setupBalls_);
    if (fittedPreset_ && tableChanged)
        if (const std::optional<CameraPose> pose = presetPose()) camera_.setPose(*pose);
    followBall();
    update();
}

void TableView::setTime(double seconds)
{
    const double end = scene_.result ? std::max(scene_.result->endTime, 0.0) : 0.0;
    if (std::isnan(seconds)) return;  // no moment to show (std::clamp would keep the NaN)
    const double t = std::clamp(seconds, 0.0, end);
    if (t == time_) return;
    time_ = t;
    followBall();
    update();
}

void TableView::setSelectedBall(int index)
{
    if (index == selectedBall_) return;
    selectedBall_ = index;
    followBall();
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

void TableView::setPathScope(BallScope scope)
{
    if (scope == pathScope_) return;
    pathScope_ = scope;
    update();
    emit displayModesChanged();
}

void TableView::setLabelScope(BallScope scope)
{
    if (scope == labelScope_) return;
    labelScope_ = scope;
    update();
    emit displayModesChanged();
}

std::optional<CameraPose> TableView::presetPose() const
{
    if (!fittedPreset_) return std::nullopt;
    return OrbitCamera::presetPose(*fittedPreset_, presetFrameFor(scene_, aspect()));
}

void TableView::setCameraPreset(CameraPreset preset, bool animated)
{
    fittedPreset_ = preset;
    follow_ = false;
    animator_->moveTo(*presetPose(), animated ? kPresetTransitionS : 0.0f);
    update();
}

void TableView::cameraMovedByHand()
{
    fittedPreset_.reset();
    if (follow_) {
        follow_ = false;
        emit displayModesChanged();
    }
}

void TableView::setFollowSelectedBall(bool follow)
{
    if (follow == follow_) return;
    follow_ = follow;
    if (follow_) fittedPreset_.reset();
    followBall();
    update();
    emit displayModesChanged();
}

// Keeps the selected ball under the camera's target, at once (playback moves it every frame).
void TableView::followBall()
{
    if (!follow_ || !scene_.result || selectedBall_ < 0 ||
        static_cast<std::size_t>(selectedBall_) >= scene_.result->balls.size())
        return;
    const BallState s = scene_.result->timelines.empty() ? scene_.result->balls[static_cast<std::size_t>(selectedBall_)].state
                                                         : scene_.result->stateAt(selectedBall_, time_);
    if (s.motion == MotionState::Pocketed) return;
    animator_->stop();
    camera_.centreOn(QVector3D(static_cast<float>(s.position.x()), static_cast<float>(s.position.y()), 0.0f));
}

void TableView::zoomToSelection(bool animated)
{
    if (!scene_.result) return;
    const SimulationResult& r = *scene_.result;
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    auto include = [&](const Vec2& p) {
        x0 = std::min(x0, p.x());
        x1 = std::max(x1, p.x());
        y0 = std::min(y0, p.y());
        y1 = std::max(y1, p.y());
    };
    // A selected event: its balls where it happens, with room around them for its arrows and labels.
    if (highlightedEvent_ >= 0 && static_cast<std::size_t>(highlightedEvent_) < r.events.size()) {
        const Event& e = r.events[static_cast<std::size_t>(highlightedEvent_)];
        double radius = 0.0;
        for (const int b : {e.balls[0], e.kind == EventKind::BallBall ? e.balls[1] : -1}) {
            if (b < 0 || static_cast<std::size_t>(b) >= r.balls.size()) continue;
            include(r.timelines.empty() ? r.balls[static_cast<std::size_t>(b)].state.position : r.stateAt(b, e.time).position);
            radius = std::max(radius, r.balls[static_cast<std::size_t>(b)].radius);
        }
        if (radius > 0.0) {
            frameBox(x0, y0, x1, y1, 8.0 * radius, animated);
            return;
        }
    }
    if (selectedBall_ < 0 || static_cast<std::size_t>(selectedBall_) >= r.balls.size()) {
        setCameraPreset(CameraPreset::Top, animated);
        return;
    }
    // The box around the ball's whole path, sampled at its segment starts and in between.
    const auto i = static_cast<std::size_t>(selectedBall_);
    include(r.balls[i].state.position);
    if (i < r.timelines.size()) {
        const double end = std::max(r.endTime, 0.0);
        for (int k = 0; k <= 200; ++k) {
            const BallState s = r.stateAt(selectedBall_, end * k / 200.0);
            if (s.motion == MotionState::Pocketed) break;
            include(s.position);
        }
    }
    frameBox(x0, y0, x1, y1, 4.0 * r.balls[i].radius, animated);
}

void TableView::frameBox(double x0, double y0, double x1, double y1, double margin, bool animated)
{
    const double w = x1 - x0 + 2.0 * margin, h = y1 - y0 + 2.0 * margin;
    CameraPose to = camera_.pose();
    to.target = QVector3D(static_cast<float>((x0 + x1) / 2.0), static_cast<float>((y0 + y1) / 2.0), 0.0f);
    // Far enough that the box fits the height and the width of the view, seen from the camera's
    // direction (exact from straight above, close enough from an angle).
    const double halfFov = OrbitCamera::kFieldOfViewDeg / 2.0 * std::numbers::pi / 180.0;
    const double fit = std::max(h, w / aspect()) / (2.0 * std::tan(halfFov));
    to.distance = static_cast<float>(std::max(fit * 1.1, 0.3));
    fittedPreset_.reset();
    animator_->moveTo(to, animated ? kPresetTransitionS : 0.0f);
    update();
}

void TableView::setSetupBalls(std::vector<Ball> balls)
{
    setupBalls_ = std::move(balls);
    if (renderer_) renderer_->setSetupBalls(setupBalls_);
    update();
}

const std::vector<Ball>& TableView::setupBalls() const
{
    static const std::vector<Ball> none;
    if (!scene_.result) return none;
    return setupBalls_.size() == scene_.result->balls.size() ? setupBalls_ : scene_.result->balls;
}

void TableView::setLayer(const QString& name, ViewLayer layer)
{
    layers_[name] = std::move(layer);
    if (renderer_) renderer_->setLayers(layers_);
    update();
}

void TableView::clearLayer(const QString& name)
{
    if (layers_.erase(name) == 0) return;
    if (renderer_) renderer_->setLayers(layers_);
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
        if (isOutOfPlay(s.motion)) continue;
        const double radius = r.balls[i].radius;
        // |o + t d - c|^2 = R^2 with |d| = 1: t = b -+ sqrt(b^2 - |o - c|^2 + R^2), b = (c - o).d
        const Vec3 c(s.position.x(), s.position.y(), radius + s.z);
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
    if (best >= 0) return best;
    // A small ball on screen (a whole table in a small view) is hard to hit: a press within
    // kPickRadiusPx of a ball's centre on screen (or within its drawn radius, if larger) picks the
    // nearest such ball, not the cloth or a construction beside it.
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < r.balls.size(); ++i) {
        const BallState s = r.timelines.empty() ? r.balls[i].state : r.stateAt(static_cast<int>(i), time_);
        if (isOutOfPlay(s.motion)) continue;
        const auto radius = static_cast<float>(r.balls[i].radius);
        const QVector3D centre(static_cast<float>(s.position.x()), static_cast<float>(s.position.y()),
                               radius + static_cast<float>(s.z));
        const std::optional<QPointF> at = widgetPointOf(centre);
        const std::optional<QPointF> rim = widgetPointOf(centre + QVector3D(radius, 0.0f, 0.0f));
        if (!at) continue;
        const double drawn = rim ? QLineF(*at, *rim).length() : 0.0;
        const double distance = QLineF(*at, widgetPos).length();
        if (distance <= std::max(kPickRadiusPx, drawn) && distance < nearest) {
            nearest = distance;
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

std::optional<QPointF> TableView::widgetPointOf(const QVector3D& world) const
{
    const std::optional<QPointF> ndc = camera_.project(world, aspect());
    if (!ndc) return std::nullopt;
    return QPointF((ndc->x() + 1.0) / 2.0 * width(), (1.0 - ndc->y()) / 2.0 * height());
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
    renderer_->setLayers(layers_);
    renderer_->setSetupBalls(setupBalls_);
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
    // A preset the user has not moved away from stays fitted (during its transition too).
    if (const std::optional<CameraPose> pose = presetPose())
        animator_->moveTo(*pose, animator_->running() ? kPresetTransitionS / 2.0f : 0.0f);
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
    frame.devicePixelRatio = static_cast<float>(devicePixelRatioF());
    frame.pixelAngle = pixelAngle(frame.viewportPixels.height());
    frame.time = time_;
    frame.overlays = overlays_;
    frame.selectedBall = selectedBall_;
    frame.highlightedEvent = highlightedEvent_;
    frame.pathScope = pathScope_;
    renderer_->setVelocityDrag(interaction_->velocityDrag());
    renderer_->render(frame);
    // While the camera moves the table is drawn without its antialiased cache; once it has been still
    // for kSettleMs, one more frame draws it antialiased.
    if (renderer_->tableUncached()) settleTimer_.start();
    lastGlError_ = glGetError();
    while (glGetError() != GL_NO_ERROR) {
    }

    QPainter painter(this);
    paintOverlayLabels(painter, scene_,
                       LabelFrame{frame.viewProjection, size(), time_, overlays_, highlightedEvent_, selectedBall_,
                                  labelScope_, &layers_, pathScope_});
    aim_->paint(painter, hovered_);
    painter.end();
    meter_->frameDrawn();
}

void TableView::mousePressEvent(QMouseEvent* event) { interaction_->press(event); }
void TableView::mouseMoveEvent(QMouseEvent* event)
{
    if (event->buttons() != Qt::NoButton) return interaction_->move(event);
    const AimHandle hovered = interaction_->hover(event->position());
    if (hovered != hovered_) {
        hovered_ = hovered;
        update();
    }
}
void TableView::mouseReleaseEvent(QMouseEvent* event) { interaction_->release(event); }
void TableView::mouseDoubleClickEvent(QMouseEvent* event) { interaction_->doubleClick(event); }
void TableView::wheelEvent(QWheelEvent* event) { interaction_->wheel(event); }

void TableView::keyPressEvent(QKeyEvent* event)
{
    // A locked view takes the aiming keys (they do nothing else here) and says why they do nothing.
    if (!editLock_.isEmpty() && AimDrag::isAimingKey(event)) {
        emit editRefused(editLock_);
        return;
    }
    if (!aim_->keyPress(event)) QOpenGLWidget::keyPressEvent(event);
}

void TableView::setEditLock(const QString& why)
{
    if (why == editLock_) return;
    editLock_ = why;
    // What the cursor is over can no longer be dragged: the cursor and the highlight say so at once.
    if (!why.isEmpty() && hovered_ != AimHandle::None) {
        hovered_ = AimHandle::None;
        unsetCursor();
        update();
    }
}

void TableView::keyReleaseEvent(QKeyEvent* event)
{
    if (!aim_->keyRelease(event)) QOpenGLWidget::keyReleaseEvent(event);
}

void TableView::leaveEvent(QEvent* event)
{
    if (hovered_ != AimHandle::None) {
        hovered_ = AimHandle::None;
        update();
    }
    QOpenGLWidget::leaveEvent(event);
}

bool TableView::event(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        // What the cursor is over as the last move found it (a ball in front of the cue wins).
        const auto* help = static_cast<QHelpEvent*>(event);
        const QString tip = AimDrag::toolTipFor(interaction_->hover(help->pos()));
        if (tip.isEmpty()) {
            QToolTip::hideText();
            event->ignore();
        } else {
            QToolTip::showText(help->globalPos(), tip, this);
        }
        return true;
    }
    return QOpenGLWidget::event(event);
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
