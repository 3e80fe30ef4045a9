// cuelab-dragbench: the frame rate of the window while a ball is dragged in the 16-ball break (issue 39),
// at 1600x1000 under a real X server (run with xvfb-run -a; Mesa's llvmpipe renders). The cue ball is
// pressed and moved with real mouse events on the table view, a small step each time the view has
// shown a new frame, for SECONDS (argument 1, default 5); every step re-simulates the break. Prints one
// JSON object: {"drag_fps": ..., "frames": N, "moves": M, "results": R, "size": "1600x1000"}: frames the
// view drew per second, the moves sent, and the results the document published meanwhile.

#include "MainWindow.h"
#include "editor/Document.h"
#include "view/TableView.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QMouseEvent>
#include <QSurfaceFormat>
#include <QTest>
#include <QVector3D>

#include <cmath>
#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv)
{
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QSurfaceFormat::setDefaultFormat(format);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("CueLab-bench"));  // not the user's settings
    const double seconds = argc > 1 ? std::atof(argv[1]) : 5.0;

    cuelab::MainWindow window;
    window.resize(1600, 1000);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return 1;
    if (!window.openFile(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/8-ball-break.json"))) return 1;
    cuelab::Document* document = window.document();
    document->waitForResult();
    auto* view = window.findChild<cuelab::TableView*>();
    QTest::qWait(300);

    const cuelab::Vec2 start = document->setup().balls.front().state.position;
    const auto at = [&](const cuelab::Vec2& p) {
        return view->widgetPointOf(QVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()), 0.0f));
    };
    const std::optional<QPointF> grab = at(start);
    if (!grab) return 1;
    long long frames = 0, results = 0;
    QObject::connect(view, &QOpenGLWidget::frameSwapped, [&] { ++frames; });
    QObject::connect(document, &cuelab::Document::resultChanged, [&] { ++results; });
    auto send = [&](QEvent::Type type, const QPointF& p, Qt::MouseButtons buttons) {
        QMouseEvent e(type, p, view->mapToGlobal(p), Qt::LeftButton, buttons, Qt::NoModifier);
        QApplication::sendEvent(view, &e);
    };
    send(QEvent::MouseButtonPress, *grab, Qt::LeftButton);
    QElapsedTimer clock;
    clock.start();
    long long moves = 0;
    const long long framesAtStart = frames;
    while (static_cast<double>(clock.elapsed()) < seconds * 1000.0) {
        // A slow circle of 5 cm around the start: the cue ball stays on the cloth and clear of the rack.
        const double a = 0.05 * static_cast<double>(moves);
        const std::optional<QPointF> p = at(start + 0.05 * cuelab::Vec2(std::cos(a) - 1.0, std::sin(a)));
        if (!p) return 1;
        send(QEvent::MouseMove, *p, Qt::LeftButton);
        ++moves;
        const long long before = frames;
        QElapsedTimer wait;
        wait.start();
        while (frames == before && wait.elapsed() < 1000) QApplication::processEvents(QEventLoop::AllEvents, 5);
    }
    const double elapsed = static_cast<double>(clock.elapsed()) / 1000.0;
    send(QEvent::MouseButtonRelease, *at(document->setup().balls.front().state.position), Qt::NoButton);
    std::printf("{\"drag_fps\": %.2f, \"frames\": %lld, \"moves\": %lld, \"results\": %lld, \"size\": \"%dx%d\"}\n",
                static_cast<double>(frames - framesAtStart) / elapsed, frames - framesAtStart, moves, results,
                window.width(), window.height());
    return 0;
}
