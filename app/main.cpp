// cuelab: the editor and analysis window.

#include "MainWindow.h"
#include "OpenGLProbe.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QMessageBox>
#include <QSurfaceFormat>

int main(int argc, char* argv[])
{
    // Every GL widget shares this format: OpenGL 3.3 core, multisampled.
    QSurfaceFormat format;
    format.setVersion(cuelab::kGlMajor, cuelab::kGlMinor);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setSamples(4);
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
    parser.process(app);

    QString problem;
    if (!cuelab::probeOpenGL(&problem)) {
        QMessageBox::critical(nullptr, QStringLiteral("CueLab"), problem);
        return 1;
    }

    MainWindow window;
    window.show();
    return QApplication::exec();
}
