#pragma once
// `cuelab --screenshot OUT.mp4|OUT.webm|OUT.gif SETUP [--slow F] [--fps N] [--camera ...] [--size WxH]`
// (issue 22, item 5; CONTRACT.md): a slow-motion video of the shot without a window, made by the same
// VideoExportJob as File > Export > Video. Kept beside HeadlessScreenshot, which hands videos here.

#include "view/OrbitCamera.h"
#include "view/ViewScene.h"

#include <QSize>

class QCommandLineParser;
class QString;

namespace cuelab {

// A video's size when --size is not given (pixels): 720p, quick to encode and small to share.
inline const QSize kDefaultVideoSize{1280, 720};

void addVideoOptions(QCommandLineParser& parser);

// Writes the video; the process's exit status (0 written, 1 not written, 2 usage error). Prints the
// frame count, duration and encoding time on stderr when the environment has CUELAB_VIDEO_STATS=1.
int takeVideo(const QCommandLineParser& parser, const QString& out, const ViewScene& scene, CameraPreset camera, QSize size);

}  // namespace cuelab
