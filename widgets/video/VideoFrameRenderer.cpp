#include "VideoFrameRenderer.h"

#include "i18n/UiNumbers.h"

#include "OpenGLProbe.h"
#include "view/OverlayLabels.h"
#include "view/RenderFrame.h"
#include "view/TableRenderer.h"

#include <QCoreApplication>
#include <QFont>
#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QPainter>
#include <QSurfaceFormat>

#include <algorithm>
#include <cmath>

namespace cuelab {

VideoFrameRenderer::VideoFrameRenderer(ViewScene scene, const SceneImageRenderer& look, const CameraPose& pose, QSize size)
    : scene_(std::move(scene)), look_(look), pose_(pose), size_(size)
{
}

VideoFrameRenderer::~VideoFrameRenderer()
{
    if (context_ && surface_ && context_->makeCurrent(surface_.get())) {
        if (renderer_) renderer_->release();
        renderer_.reset();
        fbo_.reset();
        context_->doneCurrent();
    }
}

bool VideoFrameRenderer::initialize(QString* error)
{
    auto fail = [error](const QString& message) {
        if (error) *error = message;
        return false;
    };
    if (!qobject_cast<QGuiApplication*>(QCoreApplication::instance()))
        return fail(QStringLiteral("Rendering a video needs a QGuiApplication."));
    if (!scene_.result) return fail(QStringLiteral("There is no simulation to draw."));
    if (size_.width() < 16 || size_.height() < 16 || size_.width() > 8192 || size_.height() > 8192)
        return fail(QStringLiteral("The video size %1x%2 is outside 16x16 to 8192x8192 pixels.").arg(size_.width()).arg(size_.height()));
    QSurfaceFormat format;
    format.setVersion(kGlMajor, kGlMinor);
    format.setProfile(QSurfaceFormat::CoreProfile);
    context_ = std::make_unique<QOpenGLContext>();
    context_->setFormat(format);
    if (!context_->create())
        return fail(QStringLiteral("Could not create an OpenGL %1.%2 context for the video; check the graphics driver "
                                   "(for example Mesa's libgl1-mesa-dri).")
                        .arg(kGlMajor)
                        .arg(kGlMinor));
    surface_ = std::make_unique<QOffscreenSurface>();
    surface_->setFormat(context_->format());
    surface_->create();
    if (!surface_->isValid() || !context_->makeCurrent(surface_.get()))
        return fail(QStringLiteral("Could not make the video's OpenGL context current."));
    QOpenGLFramebufferObjectFormat fboFormat;
    fboFormat.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);
    fboFormat.setSamples(0);  // as the view's and the screenshot's
    fbo_ = std::make_unique<QOpenGLFramebufferObject>(size_, fboFormat);
    if (!fbo_->isValid())
        return fail(QStringLiteral("Could not create a %1x%2 framebuffer for the video.").arg(size_.width()).arg(size_.height()));
    renderer_ = std::make_unique<TableRenderer>();
    QString problem;
    if (!renderer_->initialize(&problem)) {
        renderer_.reset();
        return fail(problem);
    }
    renderer_->setScene(scene_);
    renderer_->setLayers(look_.layers());
    context_->doneCurrent();
    return true;
}

void VideoFrameRenderer::draw(double time)
{
    const float aspect = static_cast<float>(size_.width()) / static_cast<float>(size_.height());
    OrbitCamera camera;
    camera.setPose(pose_);
    RenderFrame frame;
    frame.viewProjection = camera.projection(aspect) * camera.viewMatrix();
    frame.eye = camera.eye();
    frame.cameraUp = camera.up();
    frame.viewportPixels = size_;
    frame.pixelAngle = pixelAngle(size_.height());
    frame.time = time;
    frame.overlays = look_.overlays();
    frame.selectedBall = look_.selectedBall();
    frame.highlightedEvent = look_.highlightedEvent();
    frame.pathScope = look_.pathScope();
    renderer_->render(frame);
}

QImage VideoFrameRenderer::render(double time)
{
    if (!renderer_ || !context_->makeCurrent(surface_.get())) return {};
    const double t = std::clamp(std::isfinite(time) ? time : 0.0, 0.0, std::max(scene_.result->endTime, 0.0));
    fbo_->bind();
    draw(t);
    // The first frame of a camera draws the table without its antialiased cache (TableRenderer);
    // the camera never moves in a video, so that happens once, and the frame is drawn again cached.
    if (renderer_->tableUncached()) draw(t);
    QImage image = fbo_->toImage().convertToFormat(QImage::Format_ARGB32_Premultiplied);
    fbo_->release();
    context_->doneCurrent();
    const float aspect = static_cast<float>(size_.width()) / static_cast<float>(size_.height());
    OrbitCamera camera;
    camera.setPose(pose_);
    QPainter painter(&image);
    const ViewLayers& layers = look_.layers();
    paintOverlayLabels(painter, scene_,
                       LabelFrame{camera.projection(aspect) * camera.viewMatrix(), size_, t, look_.overlays(),
                                  look_.highlightedEvent(), look_.selectedBall(), look_.labelScope(), &layers, look_.pathScope()});
    painter.end();
    return image;
}

void stampVideoTime(QImage& frame, double time, double slow)
{
    QPainter painter(&frame);
    painter.setRenderHint(QPainter::Antialiasing);
    QFont font = painter.font();
    font.setPixelSize(std::max(12, frame.height() / 24));
    font.setBold(true);
    painter.setFont(font);
    QString text = QCoreApplication::translate("cuelab::VideoExport", "t = %1 s").arg(uiNumber(time, 3));
    if (slow != 1.0)
        text += QStringLiteral("   ") + QCoreApplication::translate("cuelab::VideoExport", "%1× slower").arg(uiSignificant(slow, 4));
    const QRect box = painter.fontMetrics().boundingRect(text).adjusted(-8, -4, 8, 4);
    const QPoint at(frame.height() / 40 + 8, frame.height() / 40 + painter.fontMetrics().ascent() + 4);
    painter.fillRect(box.translated(at), QColor(0, 0, 0, 160));
    painter.setPen(Qt::white);
    painter.drawText(at, text);
}

}  // namespace cuelab
