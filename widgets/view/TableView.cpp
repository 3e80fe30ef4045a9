// FIRST CUT: the API of the table view with camera and state handling; drawing lands next.
#include "TableView.h"

#include "TableRenderer.h"

#include <QMouseEvent>
#include <QWheelEvent>

namespace cuelab {

TableView::TableView(QWidget* parent) : QOpenGLWidget(parent)
{
    overlays_.set();
    setMouseTracking(false);
}

TableView::~TableView() = default;

void TableView::setScene(ViewScene scene)
{
    scene_ = std::move(scene);
    update();
}

void TableView::setTime(double seconds)
{
    const double end = scene_.result ? scene_.result->endTime : 0.0;
    time_ = std::clamp(seconds, 0.0, end);
    update();
}

void TableView::setSelectedBall(int index)
{
    selectedBall_ = index;
    update();
}

void TableView::setHighlightedEvent(int index)
{
    highlightedEvent_ = index;
    update();
}

void TableView::setOverlayVisible(Overlay overlay, bool visible)
{
    overlays_.set(static_cast<std::size_t>(overlay), visible);
    update();
}

bool TableView::overlayVisible(Overlay overlay) const { return overlays_.test(static_cast<std::size_t>(overlay)); }

void TableView::setCameraPreset(CameraPreset preset, bool animated)
{
    const CameraPose to = OrbitCamera::presetPose(preset, presetFrame());
    if (animated) camera_.transitionTo(to, 0.6f);
    else camera_.setPose(to);
    update();
}

int TableView::pickBall(const QPointF&) const { return -1; }

void TableView::initializeGL() { initializeOpenGLFunctions(); }
void TableView::resizeGL(int, int) {}
void TableView::paintGL()
{
    glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    lastGlError_ = glGetError();
}
void TableView::mousePressEvent(QMouseEvent* event) { QOpenGLWidget::mousePressEvent(event); }
void TableView::mouseMoveEvent(QMouseEvent* event) { QOpenGLWidget::mouseMoveEvent(event); }
void TableView::mouseReleaseEvent(QMouseEvent* event) { QOpenGLWidget::mouseReleaseEvent(event); }
void TableView::mouseDoubleClickEvent(QMouseEvent* event) { QOpenGLWidget::mouseDoubleClickEvent(event); }
void TableView::wheelEvent(QWheelEvent* event) { QOpenGLWidget::wheelEvent(event); }

float TableView::aspect() const { return height() > 0 ? static_cast<float>(width()) / static_cast<float>(height()) : 1.0f; }
QPointF TableView::toNdc(const QPointF& p) const
{
    return QPointF(2.0 * p.x() / std::max(1, width()) - 1.0, 1.0 - 2.0 * p.y() / std::max(1, height()));
}
PresetFrame TableView::presetFrame() const
{
    PresetFrame f;
    f.aspect = aspect();
    return f;
}
void TableView::releaseGl() {}
void TableView::stepCameraAnimation() {}
void TableView::countFrame() {}

}  // namespace cuelab
