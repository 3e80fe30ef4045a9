// cuelab: the editor and analysis window, and `cuelab --screenshot` to render a setup to a PNG
// without showing a window.

#include "MainWindow.h"
#include "OpenGLProbe.h"
#include "view/Screenshot.h"

#include "SetupFile.h"
#include "Simulation.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QMessageBox>
#include <QSurfaceFormat>
#include <QTimer>

#include <cstdio>
#include <memory>

namespace {

// Exit statuses of --screenshot, in the spirit of cuelab-cli (CONTRACT.md).
constexpr int kExitOk = 0;
constexpr int kExitRefused = 1;  // the setup was refused, or the picture could not be made
constexpr int kExitUsage = 2;

void printError(const QString& message) { std::fprintf(stderr, "cuelab: %s\n", qPrintable(message)); }

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
    cuelab::CameraPreset camera = cuelab::CameraPreset::Top;
    const QString cameraName = parser.value(QStringLiteral("camera"));
    if (cameraName == QLatin1String("player")) camera = cuelab::CameraPreset::Player;
    else if (cameraName == QLatin1String("side")) camera = cuelab::CameraPreset::Side;
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
    const std::optional<cuelab::Setup> setup = cuelab::io::loadSetup(args.front(), &error);
    if (!setup) {
        printError(error);
        return kExitRefused;
    }
    cuelab::ViewScene scene;
    scene.result = std::make_shared<const cuelab::SimulationResult>(cuelab::simulate(*setup));
    scene.shot = setup->shot;
    QImage image;
    if (!cuelab::renderSceneToImage(scene, time, camera, QSize(w, h), &image, &error)) {
        printError(error);
        return kExitRefused;
    }
    if (!image.save(out)) {
        printError(QStringLiteral("%1: cannot write the image").arg(out));
        return kExitRefused;
    }
    return kExitOk;
}

}  // namespace

int main(int argc, char* argv[])
{
    // Every GL surface shares this format: OpenGL 3.3 core with a depth buffer. No multisampling:
    // the table view antialiases its own table, balls and lines (TableView.cpp), and asking for
    // samples here would only make the OpenGL probe refuse drivers that lack them.
    QSurfaceFormat format;
    format.setVersion(cuelab::kGlMajor, cuelab::kGlMinor);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QSurfaceFormat::setDefaultFormat(format);

    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("CueLab"));
    QApplication::setOrganizationName(QStringLiteral("CueLab"));
    QApplication::setApplicationVersion(QStringLiteral(CUELAB_VERSION));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/cuelab.png")));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("CueLab: set up a billiards shot, simulate it exactly, step through it event by "
                       "event and read the mathematics of every collision."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("setup"), QStringLiteral("A setup file (.json) to open."),
                                 QStringLiteral("[setup]"));
    parser.addOption({QStringLiteral("screenshot"),
                      QStringLiteral("Render SETUP to the PNG file <out> without opening a window, then exit."),
                      QStringLiteral("out")});
    parser.addOption({QStringLiteral("time"), QStringLiteral("With --screenshot: the time shown, in seconds (default 0)."),
                      QStringLiteral("seconds"), QStringLiteral("0")});
    parser.addOption({QStringLiteral("camera"), QStringLiteral("With --screenshot: top, player or side (default top)."),
                      QStringLiteral("preset"), QStringLiteral("top")});
    parser.addOption({QStringLiteral("size"), QStringLiteral("With --screenshot: image size in pixels (default 1600x900)."),
                      QStringLiteral("WxH"), QStringLiteral("1600x900")});
    parser.process(app);

    if (parser.isSet(QStringLiteral("screenshot"))) return takeScreenshot(parser, parser.value(QStringLiteral("screenshot")));

    QString problem;
    if (!cuelab::probeOpenGL(&problem)) {
        printError(problem);
        QMessageBox::critical(nullptr, QStringLiteral("CueLab"), problem);
        return 1;
    }

    cuelab::MainWindow window;
    window.show();
    window.activateWindow();  // keyboard shortcuts work at once, even without a window manager
    const QStringList args = parser.positionalArguments();
    if (!args.isEmpty()) {
        // After the window is up, so that a refused file's message has a window to sit on.
        QTimer::singleShot(0, &window, [&window, path = args.front()] { window.openFile(path); });
    }
    return QApplication::exec();
}
