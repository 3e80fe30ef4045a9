#include "HeadlessScreenshot.h"

#include "export/DiagramFiles.h"
#include "view/Screenshot.h"

#include "SetupFile.h"
#include "Simulation.h"

#include <QCommandLineParser>
#include <QImage>
#include <QString>

#include <cstdio>
#include <memory>

namespace cuelab {

namespace {

// Exit statuses of --screenshot, in the spirit of cuelab-cli (CONTRACT.md).
constexpr int kExitOk = 0;
constexpr int kExitRefused = 1;  // the setup was refused, or the picture could not be made
constexpr int kExitUsage = 2;

void printError(const QString& message) { std::fprintf(stderr, "cuelab: %s\n", qPrintable(message)); }

}  // namespace

void addScreenshotOptions(QCommandLineParser& parser)
{
    parser.addOption({QStringLiteral("screenshot"),
                      QStringLiteral("Render SETUP to <out> without opening a window, then exit: .png the table view, "
                                     ".svg or .pdf a print-style shot diagram (balls where they rest unless --time)."),
                      QStringLiteral("out")});
    parser.addOption({QStringLiteral("time"), QStringLiteral("With --screenshot: the time shown, in seconds (default 0)."),
                      QStringLiteral("seconds"), QStringLiteral("0")});
    parser.addOption({QStringLiteral("camera"), QStringLiteral("With --screenshot: top, player or side (default top)."),
                      QStringLiteral("preset"), QStringLiteral("top")});
    parser.addOption({QStringLiteral("size"), QStringLiteral("With --screenshot: image size in pixels (default 1600x900)."),
                      QStringLiteral("WxH"), QStringLiteral("1600x900")});
}

// `cuelab --screenshot OUT.png SETUP [--time T] [--camera top|player|side] [--size WxH]`
int takeScreenshot(const QCommandLineParser& parser, const QString& out)
{
    const QStringList args = parser.positionalArguments();
    if (args.size() != 1) {
        printError(QStringLiteral("--screenshot needs exactly one setup file"));
        return kExitUsage;
    }
    bool ok = true;
    const double time = parser.isSet(QStringLiteral("time")) ? parser.value(QStringLiteral("time")).toDouble(&ok) : 0.0;
    if (!ok || time < 0.0) {
        printError(QStringLiteral("--time needs a number of seconds >= 0"));
        return kExitUsage;
    }
    CameraPreset camera = CameraPreset::Top;
    const QString cameraName = parser.value(QStringLiteral("camera"));
    if (cameraName == QLatin1String("player")) camera = CameraPreset::Player;
    else if (cameraName == QLatin1String("side")) camera = CameraPreset::Side;
    else if (cameraName != QLatin1String("top")) {
        printError(QStringLiteral("--camera must be top, player or side"));
        return kExitUsage;
    }
    const QStringList size = parser.value(QStringLiteral("size")).split(QLatin1Char('x'));
    bool okW = false, okH = false;
    const int w = size.size() == 2 ? size[0].toInt(&okW) : 0;
    const int h = size.size() == 2 ? size[1].toInt(&okH) : 0;
    if (!okW || !okH || w < 16 || h < 16 || w > 8192 || h > 8192) {
        printError(QStringLiteral("--size must be WIDTHxHEIGHT in pixels, 16 to 8192 each"));
        return kExitUsage;
    }

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
        const ShotDiagram diagram(scene.result, {QString::fromStdString(setup->name), QString::fromStdString(setup->notes)},
                                  parser.isSet(QStringLiteral("time")) ? time : -1.0);
        if (!writeDiagram(diagram, out, &error)) {
            printError(error);
            return kExitRefused;
        }
        return kExitOk;
    }
    scene.shot = setup->shot;
    QImage image;
    if (!renderSceneToImage(scene, time, camera, QSize(w, h), &image, &error)) {
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
