// cuelab-dragbench: the frame rate of the window while a ball is dragged in the 16-ball break (issue 39),
// at 1600x1000 under a real X server (run with xvfb-run -a; Mesa's llvmpipe renders). The cue ball is
// pressed and moved with real mouse events on the table view, a small step each time the view has
// shown a new frame, for SECONDS (argument 1, default 5); every step re-simulates the break. Prints one
// JSON object: {"drag_fps": ..., "results_per_s": ..., "frames": N, "moves": M, "edits": E, "results": R,
// "size": "1600x1000"}: frames the view drew per second, results (simulated paths of the dragged setup)
// the document published per second, the moves sent, the edits they made and the results.

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
    cuelab::TableView* view = window.tableView();
    QTest::qWait(2000);  // the camera's flight to the new shot ends

    const cuelab::Vec2 start = document->setup().balls.front().state.position;
    const auto radius = static_cast<float>(document->setup().balls.front().radius);
    const auto at = [&](const cuelab::Vec2& p) {  // the centre of a ball there
        return view->widgetPointOf(QVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()), radius));
    };
    const std::optional<QPointF> grab = at(start);
    if (!grab) return 1;
    long long frames = 0, results = 0, edits = 0;
    QObject::connect(view, &QOpenGLWidget::frameSwapped, [&] { ++frames; });
    QObject::connect(document, &cuelab::Document::resultChanged, [&] { ++results; });
    QObject::connect(document, &cuelab::Document::setupChanged, [&] { ++edits; });

    // Moves come as a mouse sends them: one every 1/120 s (Qt delivers the latest of those that wait).
    QElapsedTimer clock;
    clock.start();
    long long moves = 0;
    const long long framesAtStart = frames;
    while (static_cast<double>(clock.elapsed()) < seconds * 1000.0) {
        // A slow circle of 5 cm around the start: the cue ball stays on the cloth and clear of the rack.
        const double a = 0.02 * static_cast<double>(moves);
        const cuelab::Vec2 p = start + 0.05 * cuelab::Vec2(std::cos(a) - 1.0, std::sin(a));
        emit view->ballDragged(0, p.x(), p.y());  // what the view says at each move of a ball's drag
        ++moves;
        const qint64 due = static_cast<qint64>(static_cast<double>(moves) * 1000.0 / 120.0);
        do QApplication::processEvents(QEventLoop::AllEvents, 2);
        while (clock.elapsed() < due);
    }
    const double elapsed = static_cast<double>(clock.elapsed()) / 1000.0;
    if (results == 0) {
        std::fprintf(stderr, "cuelab-dragbench: the moves dragged no ball (no result was published)\n");
        return 1;
    }
    emit view->ballDragFinished(0);
    std::printf("{\"drag_fps\": %.2f, \"results_per_s\": %.2f, \"frames\": %lld, \"moves\": %lld, \"edits\": %lld, \"results\": %lld, \"size\": \"%dx%d\"}\n",
                static_cast<double>(frames - framesAtStart) / elapsed, static_cast<double>(results) / elapsed, frames - framesAtStart, moves, edits, results,
                window.width(), window.height());
    return 0;
}
