// Recorded shots in the window (issue 24, item 4): a recording dropped on the window opens in the
// Recording dock, its samples are drawn over the view (layer "recording"), its residual shows per ball,
// over time and in the Outcome dock, and Fit Strike finds the recorded strike again as one undoable
// edit, with progress and Cancel.

#include "../recording/SyntheticRecording.h"

#include "Features.h"
#include "MainWindow.h"
#include "RecordingFile.h"
#include "SetupFile.h"
#include "editor/Document.h"
#include "outcome/OutcomePanel.h"
#include "recording/RecordingPanel.h"
#include "view/BallAppearance.h"
#include "view/TableView.h"

#include <QDockWidget>
#include <QMimeData>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QProgressBar>
#include <QtTest>

using namespace cuelab;

namespace {

// Drops `path` on the window as a file manager would.
void drop(MainWindow& window, const QString& path)
{
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(path)});
    const QPoint at = window.rect().center();
    QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&window, &enter);
    QDropEvent dropped(QPointF(at), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&window, &dropped);
}

QString factValue(OutcomePanel* panel, const QString& what)
{
    QTableWidget* facts = panel->factsTable();
    for (int row = 0; row < facts->rowCount(); ++row)
        if (facts->item(row, 0)->text() == what) return facts->item(row, 1)->text();
    return {};
}

}  // namespace

class TestRecordingWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void recordingAgainstTheSimulation()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openExample(QStringLiteral(":/examples/three-cushion.json")));
        window.document()->waitForResult();
        const Setup truth = window.document()->setup();
        test::SamplingOptions sampling;
        sampling.duration = 2.0;
        sampling.noise = 0.0;  // the samples are the simulation: the residual is zero
        const Recording recording = test::synthesize(truth, sampling);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("three-cushion.rec.json"));
        {
            QFile file(path);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(io::serializeRecording(recording));
        }
        drop(window, path);
        auto* panel = window.findChild<RecordingPanel*>();
        QVERIFY(panel);
        QVERIFY(panel->recording());
        QVERIFY(window.findChild<QDockWidget*>(QStringLiteral("RecordingDock"))->isVisible());
        QCOMPARE(window.document()->setup().balls.size(), truth.balls.size());  // the shot stayed
        // The residual plot whole in the dock at 1600x1000, its time axis included (issue 44's review:
        // the dock scrolled and hid the plot's lower part).
        {
            auto* dock = window.findChild<QDockWidget*>(QStringLiteral("RecordingDock"));
            auto* chart = panel->findChild<QWidget*>(QStringLiteral("recordingResidual"));
            QVERIFY(chart);
            const auto whole = [&] {
                const QRect r(chart->mapTo(dock, QPoint(0, 0)), chart->size());
                return chart->isVisible() && dock->rect().contains(r) && r.height() >= 140;
            };
            QTRY_VERIFY2(whole(), qPrintable(QStringLiteral("chart at %1, height %2; dock height %3")
                                                 .arg(chart->mapTo(dock, QPoint(0, 0)).y()).arg(chart->height()).arg(dock->height())));
        }
        // The samples over the view: one dot per sample, one ghost per recorded ball.
        const ViewLayers& layers = window.tableView()->layers();
        QVERIFY(layers.count(QStringLiteral("recording")));
        std::size_t samples = 0;
        for (const RecordedBall& b : recording.balls) samples += b.samples.size();
        QCOMPARE(layers.at(QStringLiteral("recording")).markers.size(), samples);
        QCOMPARE(layers.at(QStringLiteral("recording")).ghosts.size(), recording.balls.size());
        // Each ball's dots are its path's colour (one colour per ball, lifted off the cloth's).
        {
            const ViewLayer& layer = layers.at(QStringLiteral("recording"));
            std::size_t m = 0;
            for (const RecordedBall& b : recording.balls) {
                const QVector3D line = pathColour(ballLook(truth.table.kind, b.id), truth.table.kind);
                for (std::size_t k = 0; k < b.samples.size(); ++k, ++m) {
                    const QColor c = layer.markers[m].colour;
                    QVERIFY2(std::abs(c.redF() - line.x()) < 2e-3 && std::abs(c.greenF() - line.y()) < 2e-3 &&
                                 std::abs(c.blueF() - line.z()) < 2e-3,
                             b.id.c_str());
                }
            }
        }
        // The residual: zero, per ball and over time.
        QVERIFY(panel->residual());
        QVERIFY2(panel->residual()->rmse < 1e-9, qPrintable(QString::number(panel->residual()->rmse)));
        QCOMPARE(int(panel->residual()->samples.size()), int(samples));
        QCOMPARE(panel->ballsTable()->rowCount(), int(recording.balls.size()));
        // The residual as CSV: a header and a line per sample.
        QCOMPARE(int(panel->residualCsv().count('\n')), int(samples) + 1);
        QVERIFY(panel->exportResidualsAction()->isEnabled());
        auto* outcome = window.findChild<OutcomePanel*>();
        QVERIFY2(factValue(outcome, QStringLiteral("Against the recording")).startsWith(QStringLiteral("struck ball 0.00 cm")),
                 qPrintable(factValue(outcome, QStringLiteral("Against the recording"))));

        // Aim 1.5° off: the residual grows; Fit Strike finds the heading again, as one undo step.
        std::optional<CueStrike> shot = truth.shot;
        shot->headingDeg += 1.5;
        QVERIFY(window.document()->setShot(shot, QStringLiteral("Heading"), 0));
        window.document()->waitForResult();
        QTRY_VERIFY(panel->residual() && panel->residual()->rmse > 0.01);
        QVERIFY(panel->fitButton()->isEnabled());
        const int steps = window.document()->undoStack()->count();
        QSignalSpy finished(panel, &RecordingPanel::fitFinished);
        // The progress moves while the fit runs (it stood at 0 % until the end before): every value
        // the bar takes is watched, so a fit that ends between two looks of a poll still counts.
        auto* progress = panel->findChild<QProgressBar*>(QStringLiteral("recordingProgress"));
        QVERIFY(progress);
        int seen = 0;
        const QMetaObject::Connection watch = connect(progress, &QProgressBar::valueChanged, this, [&](int value) {
            if (progress->maximum() == 1000 && value > 0 && value < 1000) seen = std::max(seen, value);
        });
        panel->fitStrike();
        QVERIFY(panel->isFitting());
        for (int i = 0; i < 2400 && finished.isEmpty(); ++i) QTest::qWait(50);
        disconnect(watch);
        QVERIFY2(seen > 0 && seen < 1000, qPrintable(QString::number(seen)));
        QVERIFY(!finished.isEmpty() || finished.wait(120000));
        QVERIFY2(finished.front().at(0).toBool(), qPrintable(finished.front().at(1).toString()));
        QCOMPARE(window.document()->undoStack()->count(), steps + 1);
        const CueStrike fitted = *window.document()->setup().shot;
        qInfo("fitted heading %.5f (true %.5f), speed %.5f (true %.5f): %s", fitted.headingDeg, truth.shot->headingDeg,
              fitted.speed, truth.shot->speed, qPrintable(finished.front().at(1).toString()));
        QVERIFY2(std::abs(fitted.headingDeg - truth.shot->headingDeg) < 0.05, qPrintable(QString::number(fitted.headingDeg)));
        QVERIFY2(std::abs(fitted.speed / truth.shot->speed - 1.0) < 0.01, qPrintable(QString::number(fitted.speed)));
        window.document()->waitForResult();
        QTRY_VERIFY(panel->residual() && panel->residual()->rmse < 0.005);
        window.document()->undoStack()->undo();
        QCOMPARE(window.document()->setup().shot->headingDeg, shot->headingDeg);

        // Cancel: the shot stays as it was.
        QSignalSpy cancelled(panel, &RecordingPanel::fitFinished);
        panel->fitStrike();
        panel->cancelFit();
        QVERIFY(cancelled.wait(120000));
        QVERIFY(!cancelled.front().at(0).toBool());
        QCOMPARE(window.document()->setup().shot->headingDeg, shot->headingDeg);
        QCOMPARE(window.document()->undoStack()->count(), steps + 1);  // the fit's step is still there to redo
    }

    // Calibrate Cloth finds the rolling resistance the recording was made with, together with the
    // strike, as one undoable edit.
    void calibrateClothToTheRecording()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openExample(QStringLiteral(":/examples/three-cushion.json")));
        window.document()->waitForResult();
        const Setup opened = window.document()->setup();
        Setup truth = opened;
        truth.physics.muRoll = opened.physics.muRoll * 1.5;  // the recorded cloth is slower
        test::SamplingOptions sampling;
        sampling.duration = 3.0;
        const Recording recording = test::synthesize(truth, sampling);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("slow-cloth.rec.json"));
        {
            QFile file(path);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(io::serializeRecording(recording));
        }
        QVERIFY(openRecording(window, path, false));
        auto* panel = window.findChild<RecordingPanel*>();
        QTRY_VERIFY(panel->calibrateButton()->isEnabled());
        const int steps = window.document()->undoStack()->count();
        QSignalSpy finished(panel, &RecordingPanel::fitFinished);
        panel->calibrateCloth();
        QVERIFY(panel->isFitting());
        QVERIFY(finished.wait(300000));
        QVERIFY2(finished.front().at(0).toBool(), qPrintable(finished.front().at(1).toString()));
        QCOMPARE(window.document()->undoStack()->count(), steps + 1);
        const double muRoll = window.document()->setup().physics.muRoll;
        qInfo("calibrated mu_roll %.5f (recorded with %.5f): %s", muRoll, truth.physics.muRoll,
              qPrintable(finished.front().at(1).toString()));
        QVERIFY2(std::abs(muRoll / truth.physics.muRoll - 1.0) < 0.1,
                 qPrintable(QStringLiteral("mu_roll %1, recorded with %2").arg(muRoll).arg(truth.physics.muRoll)));
        window.document()->undoStack()->undo();
        QCOMPARE(window.document()->setup().physics.muRoll, opened.physics.muRoll);
        QCOMPARE(window.document()->setup().shot->headingDeg, opened.shot->headingDeg);
    }

    // A recording of balls the shot lacks starts a new shot from the recording (cuelab --recording):
    // its balls where first tracked, the strike guessed, the residual shown.
    void recordingStartsItsOwnShot()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QString error;
        const std::optional<Setup> truth = io::loadSetup(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/three-cushion.json"), &error);
        QVERIFY2(truth, qPrintable(error));
        test::SamplingOptions sampling;
        sampling.duration = 2.0;
        const Recording recording = test::synthesize(*truth, sampling);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("three.rec.json"));
        {
            QFile file(path);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(io::serializeRecording(recording));
        }
        QVERIFY(openRecording(window, path, false));
        const Setup& setup = window.document()->setup();
        QCOMPARE(setup.balls.size(), recording.balls.size());
        for (std::size_t i = 0; i < setup.balls.size(); ++i) {
            QCOMPARE(setup.balls[i].id, recording.balls[i].id);
            // At the first sample (5 mm noise), or the nearest legal spot to it.
            QVERIFY((setup.balls[i].state.position - recording.balls[i].samples.front().position).norm() < 0.03);
        }
        QVERIFY(setup.shot && setup.shot->ball == truth->shot->ball);
        window.document()->waitForResult();
        auto* panel = window.findChild<RecordingPanel*>();
        QTRY_VERIFY(panel->residual().has_value());
        QVERIFY(!panel->summary().isEmpty());
    }

    // A recording of balls the shot lacks, refused or broken files.
    void brokenRecordingIsRefused()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("broken.csv"));
        {
            QFile file(path);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write("t,ball,x,y\n0,cue,0.5,0.5\n0,cue,0.6,0.5\n");
        }
        QTimer::singleShot(0, &window, [] {
            // The refusal's message box: close it.
            QTRY_VERIFY(QApplication::activeModalWidget());
            QApplication::activeModalWidget()->close();
        });
        drop(window, path);
        QVERIFY(!window.findChild<RecordingPanel*>()->recording());
    }
};

QTEST_MAIN(TestRecordingWindow)
#include "tst_recordingwindow.moc"
