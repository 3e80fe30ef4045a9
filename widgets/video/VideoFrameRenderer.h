#pragma once
// Renders the frames of a video (issue 22, item 5): the scene drawn as SceneImageRenderer draws a
// screenshot (the same TableRenderer, layers, overlays and labels), but with one OpenGL context,
// framebuffer and renderer kept for every frame, so that a few hundred frames cost a few hundred
// draws and not as many context creations and shader compilations. Each frame is then stamped with
// its time (stampVideoTime). Lives on the thread that made it (the GUI thread: QOffscreenSurface).

#include "view/OrbitCamera.h"
#include "view/Screenshot.h"
#include "view/ViewScene.h"

#include <QImage>
#include <QSize>
#include <QString>

#include <memory>

class QOffscreenSurface;
class QOpenGLContext;
class QOpenGLFramebufferObject;

namespace cuelab {

class TableRenderer;

class VideoFrameRenderer {
public:
    // `look`: the layers, overlays, selection and scopes to draw with (rendererLike(view) for the
    // view as it is); `pose`: the camera.
    VideoFrameRenderer(ViewScene scene, const SceneImageRenderer& look, const CameraPose& pose, QSize size);
    ~VideoFrameRenderer();
    VideoFrameRenderer(const VideoFrameRenderer&) = delete;
    VideoFrameRenderer& operator=(const VideoFrameRenderer&) = delete;

    // Creates the context and the renderer; false with a message a person can act on.
    bool initialize(QString* error);
    // The scene at `time` (s, clamped to the run), without the time stamp. initialize() first.
    QImage render(double time);

private:
    void draw(double time);

    ViewScene scene_;
    SceneImageRenderer look_;
    CameraPose pose_;
    QSize size_;
    std::unique_ptr<QOpenGLContext> context_;
    std::unique_ptr<QOffscreenSurface> surface_;
    std::unique_ptr<QOpenGLFramebufferObject> fbo_;
    std::unique_ptr<TableRenderer> renderer_;
};

// Writes the time in the top-left corner of a video frame: "t = 0.250 s" and, when slowed,
// "8× slower" (the stamp every frame of a video carries; tests apply it to screenshots to compare).
void stampVideoTime(QImage& frame, double time, double slow);

}  // namespace cuelab
