#pragma once
// Renders a scene to an image without a window (QOffscreenSurface + framebuffer object), for
// `cuelab --screenshot`, documentation and tests. Needs a QGuiApplication and OpenGL 3.3 core.

#include "ViewScene.h"

#include <QImage>
#include <QSize>
#include <QString>

namespace cuelab {

// Draws `scene` at `time` (s) from the camera preset, with the overlays that the view shows by
// default, into *out (size pixels). On failure returns false and sets *error to a message a person
// can act on.
bool renderSceneToImage(const ViewScene& scene, double time, CameraPreset preset, QSize size, QImage* out,
                        QString* error);

}  // namespace cuelab
