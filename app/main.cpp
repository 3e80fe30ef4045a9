// cuelab: the editor and analysis window, and `cuelab --screenshot` to render a setup to a PNG
// without showing a window.

#include "Features.h"
#include "HeadlessScreenshot.h"
#include "MainWindow.h"
#include "OpenGLProbe.h"
#include "Translations.h"
#include "editor/Document.h"
#include "editor/Selection.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QLocale>
#include <QMessageBox>
#include <QSurfaceFormat>
#include <QTimer>
#include <QUrl>

#include <cstdio>
#include <optional>
#include <utility>

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
    cuelab::addScreenshotOptions(parser);
    parser.addOption({QStringLiteral("language"),
                      QStringLiteral("The language of the interface: en or hu (default: the system's, from LANGUAGE, "
                                     "LC_ALL, LC_MESSAGES or LANG)."),
                      QStringLiteral("code")});
    parser.addOption({QStringLiteral("layout"),
                      QStringLiteral("Open with a named layout of View > Layouts: teach, coach, edit or reset (the first "
                                     "start's)."),
                      QStringLiteral("name")});
    parser.addOption({QStringLiteral("recording"),
                      QStringLiteral("Open a recorded shot (cuelab-recording JSON or CSV) against the simulation; without "
                                     "a setup, the shot starts from the recording."),
                      QStringLiteral("file")});
    parser.addOption({QStringLiteral("event"),
                      QStringLiteral("Open with event #N of the setup selected (its time, its explanation), counted from "
                                     "1 as the Events list shows them."),
                      QStringLiteral("N")});
    parser.process(app);

    // The interface's language, before any window or picture is made (app/window/Translations.h).
    const QString language = parser.value(QStringLiteral("language"));
    if (parser.isSet(QStringLiteral("language"))) {
        const QStringList known = QStringList{QStringLiteral("en")} + cuelab::translatedLanguages();
        const QString code = QLocale::languageToCode(cuelab::interfaceLocale(language).language());
        if (!known.contains(code) && language != QLatin1String("C")) {
            cuelab::printCommandLineError(QStringLiteral("--language: expected one of %1, found '%2'")
                                              .arg(known.join(QStringLiteral(", ")), language));
            return 2;
        }
    }
    cuelab::installTranslations(cuelab::interfaceLocale(language));

    std::optional<cuelab::Arrangement> layout;
    if (parser.isSet(QStringLiteral("layout"))) {
        const QString name = parser.value(QStringLiteral("layout")).toLower();
        const std::pair<const char*, cuelab::Arrangement> known[] = {{"teach", cuelab::Arrangement::Teach},
                                                                     {"coach", cuelab::Arrangement::Coach},
                                                                     {"edit", cuelab::Arrangement::Edit},
                                                                     {"reset", cuelab::Arrangement::Default}};
        for (const auto& [key, value] : known)
            if (name == QLatin1String(key)) layout = value;
        if (!layout) {
            cuelab::printCommandLineError(QStringLiteral("--layout: expected teach, coach, edit or reset, found '%1'").arg(name));
            return 2;
        }
    }

    int event = 0;
    if (parser.isSet(QStringLiteral("event"))) {
        QString text = parser.value(QStringLiteral("event"));
        if (text.startsWith(QLatin1Char('#'))) text.remove(0, 1);
        bool ok = false;
        event = text.toInt(&ok);
        if (!ok || event < 1) {
            cuelab::printCommandLineError(QStringLiteral("--event: expected an event number from 1, found '%1'")
                                              .arg(parser.value(QStringLiteral("event"))));
            return 2;
        }
    }

    // The window's own options mean nothing to a picture: refused, not silently ignored.
    if (parser.isSet(QStringLiteral("screenshot")))
        for (const char* option : {"layout", "event", "recording"})
            if (parser.isSet(QString::fromLatin1(option))) {
                cuelab::printCommandLineError(QStringLiteral("--%1 is an option of the window, not of --screenshot").arg(QLatin1String(option)));
                return 2;
            }

    if (parser.isSet(QStringLiteral("screenshot"))) return cuelab::takeScreenshot(parser, parser.value(QStringLiteral("screenshot")));
    if (const QString stray = cuelab::strayScreenshotOption(parser); !stray.isEmpty()) {
        cuelab::printCommandLineError(QStringLiteral("--%1 is an option of --screenshot only").arg(stray));
        return 2;
    }

    QString problem;
    if (!cuelab::probeOpenGL(&problem)) {
        std::fprintf(stderr, "cuelab: %s\n", qPrintable(problem));
        QMessageBox::critical(nullptr, QStringLiteral("CueLab"), problem);
        return 1;
    }

    cuelab::MainWindow window;
    window.showOnStart();  // maximised on the first start (up to 1920 px wide), else as left
    window.activateWindow();  // keyboard shortcuts work at once, even without a window manager
    if (layout) window.arrange(*layout);
    const QStringList args = parser.positionalArguments();
    if (event > 0) {
        // Once the result of the setup asked for lands (the file's, when one is given: the document
        // is replaced first): a number beyond its events selects nothing.
        auto* once = new QObject(&window);
        const auto select = [&window, once, event] {
            QObject::connect(window.document(), &cuelab::Document::resultChanged, once, [&window, once, event] {
                const auto result = window.document()->result();
                if (!window.document()->isResultCurrent()) return;
                if (result && event <= static_cast<int>(result->events.size())) window.selection()->selectEvent(event - 1);
                once->deleteLater();
            });
        };
        if (args.isEmpty()) select();
        else QObject::connect(window.document(), &cuelab::Document::documentReplaced, once, select, Qt::SingleShotConnection);
    }
    if (!args.isEmpty()) {
        // After the window is up, so that a refused file's message has a window to sit on.
        // A launcher passes a file as a path or a file: URL (the desktop entry's %u); a cuelab: link is
        // a shot code and opens as one.
        QString path = args.front();
        if (path.startsWith(QLatin1String("file:"))) path = QUrl(path).toLocalFile();
        QTimer::singleShot(0, &window, [&window, path] { window.openFile(path); });
    }
    if (parser.isSet(QStringLiteral("recording"))) {
        // After the setup (when one is given), so that the recording meets its balls.
        QTimer::singleShot(0, &window, [&window, path = parser.value(QStringLiteral("recording"))] {
            cuelab::openRecording(window, path, false);
        });
    }
    return QApplication::exec();
}
