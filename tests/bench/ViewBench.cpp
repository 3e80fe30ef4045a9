// cuelab-viewbench: frames per second of the table view's renderer at 1600x1000 on the 8-ball break,
// offscreen (a single-sampled framebuffer, as the view's surface), every frame finished (glFinish)
// before the next. Prints one JSON object:
//   {"static_fps": ..., "orbit_fps": ..., "overlays_off_fps": ..., "frames": N, "size": "1600x1000"}
// static_fps: all overlays and their labels, fixed camera, time running through the shot;
// orbit_fps: the same with the camera orbiting a little every frame (the table must be redrawn);
// overlays_off_fps: no overlays, fixed camera, time running; labels_off_fps: the overlays without their
// labels; new_result_fps: as static_fps with the scene's result replaced every frame (a drag). Run under `xvfb-run -a`; argument 1 is N.

#include "OpenGLProbe.h"
#include "view/OverlayLabels.h"
#include "view/SceneFraming.h"
#include "SetupFile.h"
#include "Simulation.h"
#include "view/TableRenderer.h"

#include <QElapsedTimer>
#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QOpenGLPaintDevice>
#include <QPainter>
#include <QSurfaceFormat>

#include <cstdio>
#include <memory>

namespace {

constexpr int kWidth = 1600, kHeight = 1000;  // pixels

struct Pass {
    bool overlays = true;
    bool orbit = false;
    bool labels = true;      // the labels painted with QPainter over the frame
    bool newResult = false;  // the scene handed over again every frame, as while a ball is dragged
};

// Renders `frames` frames the way TableView::paintGL does (renderer, then the labels with QPainter
// on the GL paint device) and returns the frames per second.
double runPass(cuelab::TableRenderer& renderer, const cuelab::ViewScene& scene, QOpenGLFunctions& gl, int frames,
               const Pass& pass)
{
    using namespace cuelab;
    const QSize size(kWidth, kHeight);
    const float aspect = static_cast<float>(kWidth) / static_cast<float>(kHeight);
    OrbitCamera camera;
    camera.setPose(OrbitCamera::presetPose(CameraPreset::Top, presetFrameFor(scene, aspect)));
    camera.orbit(20.0f, 25.0f);  // an oblique view, so that the cushions and pockets are in sight
    const std::bitset<kOverlayCount> overlays = pass.overlays ? defaultOverlays() : std::bitset<kOverlayCount>();
    const double end = scene.result->endTime;
    QOpenGLPaintDevice device(size);
    QElapsedTimer clock;
    for (int f = -1; f < frames; ++f) {
        if (f == 0) clock.start();  // frame -1 warms the caches up and is not counted
        if (pass.orbit) camera.orbit(0.5f, 0.0f);
        if (pass.newResult) {  // a copy: the renderer sees a result it has not drawn before
            ViewScene next = scene;
            next.result = std::make_shared<const SimulationResult>(*scene.result);
            renderer.setScene(next);
        }
        RenderFrame frame;
        frame.viewProjection = camera.projection(aspect) * camera.viewMatrix();
        frame.eye = camera.eye();
        frame.cameraUp = camera.up();
        frame.viewportPixels = size;
        frame.pixelAngle = pixelAngle(kHeight);
        frame.time = end * (f + 1) / (frames + 1);  // s: time runs as when the shot plays
        frame.overlays = overlays;
        renderer.render(frame);
        if (pass.labels) {
            QPainter painter(&device);
            paintOverlayLabels(painter, scene, LabelFrame{frame.viewProjection, size, frame.time, overlays, -1});
            painter.end();
        }
        gl.glFinish();
    }
    return frames * 1000.0 / std::max<double>(1.0, static_cast<double>(clock.elapsed()));
}

}  // namespace

int main(int argc, char** argv)
{
    QGuiApplication app(argc, argv);
    const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 120;

    QString error;
    const std::optional<cuelab::Setup> setup = cuelab::io::loadSetup(QStringLiteral(":/examples/8-ball-break.json"), &error);
    if (!setup) {
        std::fprintf(stderr, "cuelab-viewbench: %s\n", qPrintable(error));
        return 1;
    }
    cuelab::ViewScene scene;
    scene.result = std::make_shared<const cuelab::SimulationResult>(cuelab::simulate(*setup));
    scene.shot = setup->shot;

    QSurfaceFormat format;
    format.setVersion(cuelab::kGlMajor, cuelab::kGlMinor);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QOpenGLContext context;
    context.setFormat(format);
    QOffscreenSurface surface;
    surface.setFormat(format);
    surface.create();
    if (!context.create() || !context.makeCurrent(&surface)) {
        std::fprintf(stderr, "cuelab-viewbench: no OpenGL %d.%d core context\n", cuelab::kGlMajor, cuelab::kGlMinor);
        return 1;
    }
    QOpenGLFramebufferObjectFormat fboFormat;
    fboFormat.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);
    fboFormat.setSamples(0);  // as the view's surface (TableView asks for a single-sampled one)
    double staticFps = 0.0, orbitFps = 0.0, offFps = 0.0, labelsOffFps = 0.0, newResultFps = 0.0;
    {
        QOpenGLFramebufferObject fbo(QSize(kWidth, kHeight), fboFormat);
        cuelab::TableRenderer renderer;
        if (!fbo.isValid() || !fbo.bind() || !renderer.initialize(&error)) {
            std::fprintf(stderr, "cuelab-viewbench: %s\n", error.isEmpty() ? "no framebuffer" : qPrintable(error));
            return 1;
        }
        renderer.setScene(scene);
        QOpenGLFunctions* gl = context.functions();
        staticFps = runPass(renderer, scene, *gl, frames, Pass{true, false});
        orbitFps = runPass(renderer, scene, *gl, frames, Pass{true, true});
        offFps = runPass(renderer, scene, *gl, frames, Pass{false, false});
        labelsOffFps = runPass(renderer, scene, *gl, frames, Pass{true, false, false});
        newResultFps = runPass(renderer, scene, *gl, frames, Pass{true, false, true, true});
        renderer.setScene(scene);
        renderer.release();
        fbo.release();
    }
    context.doneCurrent();
    std::printf("{\"static_fps\": %.1f, \"orbit_fps\": %.1f, \"overlays_off_fps\": %.1f, \"labels_off_fps\": %.1f, "
                "\"new_result_fps\": %.1f, \"frames\": %d, \"size\": \"%dx%d\"}\n",
                staticFps, orbitFps, offFps, labelsOffFps, newResultFps, frames, kWidth, kHeight);
    return 0;
}
