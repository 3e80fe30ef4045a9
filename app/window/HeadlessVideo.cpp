#include "HeadlessVideo.h"

#include "HeadlessScreenshot.h"
#include "NumberParse.h"

#include "video/VideoExport.h"
#include "view/SceneFraming.h"
#include "view/Screenshot.h"

#include <QCommandLineParser>
#include <QElapsedTimer>

#include <cstdio>
#include <optional>

namespace cuelab {

void addVideoOptions(QCommandLineParser& parser)
{
    parser.addOption({QStringLiteral("slow"),
                      QStringLiteral("With --screenshot OUT.mp4|.webm|.gif: play the shot F times slower than real time "
                                     "(1 to 1000, default 1)."),
                      QStringLiteral("F"), QStringLiteral("1")});
    parser.addOption({QStringLiteral("fps"),
                      QStringLiteral("With --screenshot OUT.mp4|.webm|.gif: frames per second (1 to 120, default 30; a GIF "
                                     "plays at 100/round(100/N))."),
                      QStringLiteral("N"), QStringLiteral("30")});
}

int takeVideo(const QCommandLineParser& parser, const QString& out, const ViewScene& scene, CameraPreset camera, QSize size)
{
    QString problem;
    const std::optional<double> slow = cmdline::parseNumber(QStringLiteral("slow"), parser.value(QStringLiteral("slow")), 1.0,
                                                            1000.0, QStringLiteral("a slow-motion factor"), &problem);
    if (!slow) {
        printCommandLineError(problem);
        return 2;
    }
    const std::optional<long long> fps =
        cmdline::parseWholeNumber(QStringLiteral("fps"), parser.value(QStringLiteral("fps")), 1, 120, &problem);
    if (!fps) {
        printCommandLineError(problem);
        return 2;
    }
    VideoRequest request;
    request.path = out;
    request.slow = *slow;
    request.fps = static_cast<double>(*fps);
    request.size = size;
    // The camera preset framed for the video's own aspect ratio, as a screenshot of that size is.
    const float aspect = static_cast<float>(size.width()) / static_cast<float>(size.height());
    const CameraPose pose = OrbitCamera::presetPose(camera, presetFrameFor(scene, aspect));
    VideoExportJob job(scene, SceneImageRenderer(), pose, request);
    QElapsedTimer clock;
    clock.start();
    QString error;
    if (!job.run(&error)) {
        printCommandLineError(error);
        return 1;
    }
    if (qEnvironmentVariableIntValue("CUELAB_VIDEO_STATS") == 1)
        std::fprintf(stderr, "cuelab: %s: %d frames, %.3f s at %.4g frames/s, made in %.2f s\n", qPrintable(out),
                     job.plan().frames, job.plan().duration(), job.plan().playedFps, static_cast<double>(clock.elapsed()) / 1000.0);
    return 0;
}

}  // namespace cuelab
