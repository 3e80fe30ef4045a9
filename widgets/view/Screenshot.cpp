#include "Screenshot.h"

#include "OpenGLProbe.h"
#include "OverlayLabels.h"
#include "SceneFraming.h"
#include "TableRenderer.h"
#include "TableView.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QPainter>
#include <QSurfaceFormat>

#include <cmath>

namespace cuelab {

bool renderSceneToImage(const ViewScene& scene, double time, CameraPreset preset, QSize size, QImage* out,
                        QString* error)
{
    return SceneImageRenderer().render(scene, time, preset, size, out, error);
}

SceneImageRenderer rendererLike(const TableView& view)
{
    SceneImageRenderer r;
    for (const auto& [name, layer] : view.layers()) r.setLayer(name, layer);
    std::bitset<kOverlayCount> overlays;
    for (int i = 0; i < kOverlayCount; ++i) overlays.set(static_cast<std::size_t>(i), view.overlayVisible(static_cast<Overlay>(i)));
    r.setOverlays(overlays);
    r.setSelectedBall(view.selectedBall());
    r.setHighlightedEvent(view.highlightedEvent());
    r.setPathScope(view.pathScope());
    r.setLabelScope(view.labelScope());
    return r;
}

bool renderCurrentView(const TableView& view, QSize size, QImage* out, QString* error)
{
    return rendererLike(view).render(view.scene(), view.time(), view.camera().pose(), size, out, error);
}

bool SceneImageRenderer::render(const ViewScene& scene, double time, CameraPreset preset, QSize size, QImage* out,
                                QString* error) const
{
    const float aspect = size.height() > 0 ? static_cast<float>(size.width()) / static_cast<float>(size.height()) : 1.0f;
    return render(scene, time, OrbitCamera::presetPose(preset, presetFrameFor(scene, aspect)), size, out, error);
}

bool SceneImageRenderer::render(const ViewScene& scene, double time, const CameraPose& pose, QSize size, QImage* out,
                                QString* error) const
{
    auto fail = [error](const QString& message) {
        if (error) *error = message;
        return false;
    };
    if (!qobject_cast<QGuiApplication*>(QCoreApplication::instance()))
        return fail(QStringLiteral("Rendering a screenshot needs a QGuiApplication."));
    if (size.width() < 16 || size.height() < 16 || size.width() > 8192 || size.height() > 8192)
        return fail(QStringLiteral("The screenshot size %1x%2 is outside 16x16 to 8192x8192 pixels.")
                        .arg(size.width())
                        .arg(size.height()));
    if (!scene.result) return fail(QStringLiteral("There is no simulation to draw."));
    if (!std::isfinite(time)) return fail(QStringLiteral("The time of a screenshot must be a finite number of seconds."));

    QSurfaceFormat format;
    format.setVersion(kGlMajor, kGlMinor);
    format.setProfile(QSurfaceFormat::CoreProfile);
    QOpenGLContext context;
    context.setFormat(format);
    if (!context.create())
        return fail(QStringLiteral("Could not create an OpenGL %1.%2 context for the screenshot; check the graphics "
                                   "driver (for example Mesa's libgl1-mesa-dri).")
                        .arg(kGlMajor)
                        .arg(kGlMinor));
    QOffscreenSurface surface;
    surface.setFormat(context.format());
    surface.create();
    if (!surface.isValid() || !context.makeCurrent(&surface))
        return fail(QStringLiteral("Could not make the screenshot's OpenGL context current."));

    QOpenGLFramebufferObjectFormat fboFormat;
    fboFormat.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);
    fboFormat.setSamples(0);  // as the view's: the renderer antialiases the table, balls and lines itself
    bool ok = false;
    {
        QOpenGLFramebufferObject fbo(size, fboFormat);
        if (fbo.isValid() && fbo.bind()) {
            TableRenderer renderer;
            QString problem;
            if (renderer.initialize(&problem)) {
                const float aspect = static_cast<float>(size.width()) / static_cast<float>(size.height());
                OrbitCamera camera;
                camera.setPose(pose);
                renderer.setScene(scene);
                renderer.setLayers(layers_);
                RenderFrame frame;
                frame.viewProjection = camera.projection(aspect) * camera.viewMatrix();
                frame.eye = camera.eye();
                frame.cameraUp = camera.up();
                frame.viewportPixels = size;
                frame.pixelAngle = pixelAngle(size.height());
                frame.time = std::clamp(time, 0.0, std::max(scene.result->endTime, 0.0));
                frame.overlays = overlays_;
                frame.selectedBall = selectedBall_;
                frame.highlightedEvent = highlightedEvent_;
                frame.pathScope = pathScope_;
                renderer.render(frame);
                *out = fbo.toImage().convertToFormat(QImage::Format_ARGB32_Premultiplied);
                QPainter painter(out);
                paintOverlayLabels(painter, scene,
                                   LabelFrame{frame.viewProjection, size, frame.time, frame.overlays, highlightedEvent_, selectedBall_,
                                              labelScope_, &layers_, pathScope_});
                painter.end();
                ok = true;
            } else if (error) {
                *error = problem;
            }
            renderer.release();
            fbo.release();
        } else if (error) {
            *error = QStringLiteral("Could not create a %1x%2 framebuffer for the screenshot.")
                         .arg(size.width())
                         .arg(size.height());
        }
    }
    context.doneCurrent();
    return ok;
}

}  // namespace cuelab
