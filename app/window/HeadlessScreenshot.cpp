#include "HeadlessScreenshot.h"

#include "HeadlessVideo.h"
#include "export/DiagramFiles.h"
#include "video/VideoEncoder.h"
#include "view/Screenshot.h"

#include "NumberParse.h"

#include "SetupFile.h"
#include "Simulation.h"

#include <QCommandLineParser>
#include <QImage>
#include <QString>

#include <cstdio>
#include <memory>
#include <optional>

namespace cuelab {

namespace {

// Exit statuses of --screenshot, in the spirit of cuelab-cli (CONTRACT.md).
constexpr int kExitOk = 0;
constexpr int kExitRefused = 1;  // the setup was refused, or the picture could not be made
constexpr int kExitUsage = 2;

void printError(const QString& message) { std::fprintf(stderr, "cuelab: %s\n", qPrintable(message)); }

}  // namespace

void printCommandLineError(const QString& message) { printError(message); }

QString strayScreenshotOption(const QCommandLineParser& parser)
{
    if (parser.isSet(QStringLiteral("screenshot"))) return {};
    for (const QString& name : {QStringLiteral("time"), QStringLiteral("camera"), QStringLiteral("size"), QStringLiteral("slow"),
                                QStringLiteral("fps")})
        if (parser.isSet(name)) return name;
    return {};
}

void addScreenshotOptions(QCommandLineParser& parser)
{
    parser.addOption({QStringLiteral("screenshot"),
                      QStringLiteral("Render SETUP to <out> without opening a window, then exit: .png the table view, "
                                     ".svg or .pdf a print-style shot diagram (balls where they rest unless --time), "
                                     ".mp4, .webm or .gif a video of the shot (--slow, --fps)."),
                      QStringLiteral("out")});
    parser.addOption({QStringLiteral("time"), QStringLiteral("With --screenshot: the time shown, in seconds (default 0)."),
                      QStringLiteral("seconds"), QStringLiteral("0")});
    parser.addOption({QStringLiteral("camera"), QStringLiteral("With --screenshot: top, player or side (default top)."),
                      QStringLiteral("preset"), QStringLiteral("top")});
    parser.addOption({QStringLiteral("size"), QStringLiteral("With --screenshot: image size in pixels (default 1600x900)."),
                      QStringLiteral("WxH"), QStringLiteral("1600x900")});
    addVideoOptions(parser);
}

// `cuelab --screenshot OUT.png SETUP [--time T] [--camera top|player|side] [--size WxH]`
int takeScreenshot(const QCommandLineParser& parser, const QString& out)
{
    const QStringList args = parser.positionalArguments();
    if (args.size() != 1) {
        printError(QStringLiteral("--screenshot needs exactly one setup file"));
        return kExitUsage;
    }
    // Numbers go through the parser cuelab-cli uses (app/common/NumberParse.h): nan, inf and absurd
    // values are usage errors naming the option, never a time handed to the renderer.
    QString problem;
    double time = 0.0;
    if (parser.isSet(QStringLiteral("time"))) {
        const std::optional<double> t = cmdline::parseSeconds(QStringLiteral("time"), parser.value(QStringLiteral("time")),
                                                              false, &problem);
        if (!t) {
            printError(problem);
            return kExitUsage;
        }
        time = *t;
    }
    CameraPreset camera = CameraPreset::Top;
    const QString cameraName = parser.value(QStringLiteral("camera"));
    if (cameraName == QLatin1String("player")) camera = CameraPreset::Player;
    else if (cameraName == QLatin1String("side")) camera = CameraPreset::Side;
    else if (cameraName != QLatin1String("top")) {
        printError(QStringLiteral("--camera: expected top, player or side, found '%1'").arg(cameraName));
        return kExitUsage;
    }
    const QString sizeText = parser.value(QStringLiteral("size"));
    const QStringList size = sizeText.split(QLatin1Char('x'));
    const std::optional<long long> w =
        size.size() == 2 ? cmdline::parseWholeNumber(QStringLiteral("size"), size[0], 16, 8192, &problem) : std::nullopt;
    const std::optional<long long> h =
        size.size() == 2 ? cmdline::parseWholeNumber(QStringLiteral("size"), size[1], 16, 8192, &problem) : std::nullopt;
    if (!w || !h) {
        printError(QStringLiteral("--size: expected WIDTHxHEIGHT in pixels, 16 to 8192 each, found '%1'").arg(sizeText));
        return kExitUsage;
    }
    const QSize pixels(static_cast<int>(*w), static_cast<int>(*h));

    VideoFormat videoFormat = VideoFormat::Mp4;
    const bool video = videoFormatOf(out, &videoFormat);
    if (!video) {
        for (const QString& name : {QStringLiteral("slow"), QStringLiteral("fps")})
            if (parser.isSet(name)) {
                printError(QStringLiteral("--%1 is an option of a video (.mp4, .webm, .gif) only").arg(name));
                return kExitUsage;
            }
    } else if (parser.isSet(QStringLiteral("time"))) {
        printError(QStringLiteral("--time is an option of a picture; a video shows the whole shot"));
        return kExitUsage;
    }
    const bool sizeGiven = parser.isSet(QStringLiteral("size"));

    QString error;
    const std::optional<Setup> setup = io::loadSetup(args.front(), &error);
    if (!setup) {
        printError(error);
        return kExitRefused;
    }
    ViewScene scene;
    scene.result = std::make_shared<const SimulationResult>(simulate(*setup));
    // SVG and PDF: the print-style shot diagram (widgets/export), at --time or else at the end.
    DiagramFormat format = DiagramFormat::Png;
    if (diagramFormatOf(out, &format) && format != DiagramFormat::Png) {
        DiagramText text{QString::fromStdString(setup->name), QString::fromStdString(setup->notes)};
        text.facts = shotFacts(*setup);
        const ShotDiagram diagram(scene.result, text, parser.isSet(QStringLiteral("time")) ? time : -1.0);
        if (!writeDiagram(diagram, out, &error)) {
            printError(error);
            return kExitRefused;
        }
        return kExitOk;
    }
    scene.shot = setup->shot;
    if (video)
        return takeVideo(parser, out, scene, camera,
                         sizeGiven ? pixels : kDefaultVideoSize);
    QImage image;
    if (!renderSceneToImage(scene, time, camera, pixels, &image, &error)) {
        printError(error);
        return kExitRefused;
    }
    if (!image.save(out)) {
        printError(QStringLiteral("%1: cannot write the image").arg(out));
        return kExitRefused;
    }
    return kExitOk;
}

}  // namespace cuelab
