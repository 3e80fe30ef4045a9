// The Compare panel: background runs that drop stale results, the chart's cursor on the transport,
// the collision table, the warnings, and the ghosts it hands the table view (in the window too).

#include "MainWindow.h"

#include "compare/CollisionTable.h"
#include "compare/CompareChart.h"
#include "compare/CompareGhosts.h"
#include "compare/ComparePanel.h"
#include "compare/CompareRunner.h"
#include "editor/Document.h"
#include "editor/Playback.h"
#include "view/TableView.h"

#include "SetupFile.h"
#include "ExampleSetup.h"

#include <QCheckBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QLineSeries>
#include <QMenu>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace cuelab;
using compare::EngineKind;

namespace {

Setup example(const char* name) { return loadExample(name); }

QDockWidget* compareDock(MainWindow& w)
{
    for (QDockWidget* d : w.panels())
        if (d->objectName() == QLatin1String("CompareDock")) return d;
    return nullptr;
}

}  // namespace

class TestComparePanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void runsAndShows();
    void chartFollowsTheTime();
    void staleResultsAreDropped();
    void runnerCancelsTheRunInProgress();
    void ghostsInTheWindow();
    void chartUnitFollowsTheError();

private:
    QTemporaryDir settingsDir_;
};

void TestComparePanel::initTestCase()
{
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir_.path());
    QCoreApplication::setOrganizationName(QStringLiteral("CueLabTests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_comparepanel"));
}

void TestComparePanel::runsAndShows()
{
    ComparePanel panel;
    QSignalSpy ghosts(&panel, &ComparePanel::ghostLayerChanged);
    panel.setSetup(example("draw-shot.json"));
    panel.setEngine(EngineKind::Box2D);
    panel.waitForIdle();
    const auto c = panel.comparison();
    QVERIFY(c);
    QCOMPARE(int(c->run.settings.engine), int(EngineKind::Box2D));
    QVERIFY(panel.warningsText().contains("the draw is lost"));
    QVERIFY(panel.summaryText().contains("Largest error"));
    // Ghosts: one track per ball, in Box2D's colour, the first labelled with the engine.
    QVERIFY(ghosts.count() >= 1);
    const ViewLayer layer = panel.ghosts();
    QCOMPARE(layer.ghosts.size(), std::size_t(2));
    QCOMPARE(layer.ghosts[0].colour, engineColour(EngineKind::Box2D));
    QCOMPARE(layer.ghosts[0].label, QStringLiteral("box2d"));
    QVERIFY(layer.ghosts[0].times.size() > 10);
    for (std::size_t i = 0; i < layer.ghosts.size(); ++i) QCOMPARE(layer.ghosts[i].ball, int(i));  // View > Paths Of finds them
    Vec2 at;
    QVERIFY(ghostPositionAt(layer.ghosts[0], 0.0, &at));
    QVERIFY((at - c->run.samples[0][0].position).norm() < 1e-12);
    // The 1 drops in the side pocket: its track ends there.
    QVERIFY(!ghostPositionAt(layer.ghosts[1], 5.0, &at));
    QVERIFY(ghostPositionAt(layer.ghosts[0], 5.0, &at));  // the cue ball stays where it stopped
    // Chart: a series per ball; collisions: both sequences.
    QCOMPARE(panel.chart()->ballSeries().size(), 2);
    QCOMPARE(panel.chart()->ballSeries()[0]->count(), int(c->divergence.times.size()));
    QVERIFY(panel.collisions()->rowCount() >= 2);
    QCOMPARE(panel.collisions()->item(0, 2)->text(), QStringLiteral("cue – 1"));
    QCOMPARE(panel.collisions()->item(0, 4)->text(), QStringLiteral("cue – 1"));
    // Switching the ghosts off hands the view an empty layer.
    auto* box = panel.findChild<QCheckBox*>();
    QVERIFY(box);
    box->setChecked(false);
    QVERIFY(!panel.ghostsEnabled());
    QVERIFY(ghosts.count() >= 2);
    // The exact engine: no ghosts, no error.
    panel.setEngine(EngineKind::Exact);
    panel.waitForIdle();
    QCOMPARE(panel.comparison()->divergence.maxError, 0.0);
    QVERIFY(panel.ghosts().empty());
}

void TestComparePanel::chartFollowsTheTime()
{
    ComparePanel panel;
    panel.setSetup(example("straight-shot.json"));
    panel.setEngine(EngineKind::Discrete);
    panel.waitForIdle();
    for (double t : {0.0, 0.5, 1.25}) {
        panel.setTime(t);
        QCOMPARE(panel.chart()->cursorTime(), t);
        const QList<QPointF> points = panel.chart()->cursor()->points();
        QCOMPARE(points.size(), 2);
        QCOMPARE(points[0].x(), t);
        QCOMPARE(points[1].x(), t);
        QVERIFY(points[1].y() > points[0].y());
    }
}

void TestComparePanel::staleResultsAreDropped()
{
    ComparePanel panel;
    QSignalSpy changed(&panel, &ComparePanel::comparisonChanged);
    panel.setSetup(example("8-ball-break.json"));
    panel.setEngine(EngineKind::Discrete);
    panel.waitForIdle();
    changed.clear();
    // Three quick changes: only the last one is shown.
    panel.setStep(0.0005);
    panel.setStep(0.002);
    panel.setSubsteps(4);
    panel.waitForIdle();
    QCOMPARE(changed.count(), 1);
    QCOMPARE(panel.comparison()->run.settings.dt, 0.002);
    QCOMPARE(panel.comparison()->run.settings.substeps, 4);
}

void TestComparePanel::runnerCancelsTheRunInProgress()
{
    CompareRunner runner;
    QSignalSpy finished(&runner, &CompareRunner::finished);
    compare::EngineSettings slow;
    slow.engine = EngineKind::Discrete;
    slow.dt = 1e-5;  // a long run: minutes if it were not cancelled
    runner.run(example("8-ball-break.json"), slow);
    QVERIFY(runner.isRunning());
    QTest::qWait(50);  // the event loop keeps going while it runs
    compare::EngineSettings quick;
    quick.engine = EngineKind::Box2D;
    QElapsedTimer clock;
    clock.start();
    runner.run(example("straight-shot.json"), quick);
    runner.waitForIdle();
    QVERIFY2(clock.elapsed() < 20000, "the slow run was cancelled");
    QCOMPARE(finished.count(), 1);
    QCOMPARE(int(runner.result()->run.settings.engine), int(EngineKind::Box2D));
    QCOMPARE(runner.result()->run.ids.size(), std::size_t(2));
}

// The chart's errors in millimetres, or in metres once one passes a metre: 1.5 m reads 1.5 on an
// axis in metres, not 1500 (or "1.5e+03") millimetres.
void TestComparePanel::chartUnitFollowsTheError()
{
    CompareChart chart;
    compare::Comparison c;
    c.run.ids = {"cue"};
    c.divergence.times = {0.0, 1.0};
    c.divergence.error = {{0.0, 1.5}};
    chart.setComparison(c);
    QCOMPARE(chart.errorAxisTitle(), QStringLiteral("error (m)"));
    QCOMPARE(chart.ballSeries()[0]->at(1).y(), 1.5);
    c.divergence.error = {{0.0, 0.0015}};
    chart.setComparison(c);
    QCOMPARE(chart.errorAxisTitle(), QStringLiteral("error (mm)"));
    QCOMPARE(chart.ballSeries()[0]->at(1).y(), 1.5);
}

void TestComparePanel::ghostsInTheWindow()
{
    MainWindow w;
    w.resize(1600, 1000);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openFile(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/draw-shot.json")));
    QDockWidget* dock = compareDock(w);
    QVERIFY(dock);
    QVERIFY(!dock->isVisible());  // hidden on the first start: nothing runs
    auto* panel = dock->findChild<ComparePanel*>();
    QVERIFY(panel);
    QVERIFY(w.tableView()->layers().count(QStringLiteral("compare")) == 0);

    // Analysis > Compare Methods opens it; Box2D runs; its ghosts appear in the view.
    QAction* open = nullptr;
    for (QAction* a : w.menu(WindowMenu::Analysis)->actions())
        if (a->text().contains(QStringLiteral("Compare"))) open = a;
    QVERIFY(open);
    open->trigger();
    QVERIFY(dock->isVisible());
    panel->setEngine(EngineKind::Box2D);
    panel->waitForIdle();
    QTRY_VERIFY(w.tableView()->layers().count(QStringLiteral("compare")) == 1);
    QCOMPARE(w.tableView()->layers().at(QStringLiteral("compare")).ghosts.size(), std::size_t(2));

    // The chart's cursor follows the transport.
    w.playback()->setTime(0.6);
    QCOMPARE(panel->chart()->cursorTime(), w.playback()->time());

    // A picture of it, for people to look at (CUELAB_SCREENSHOT_DIR).
    const QByteArray dir = qgetenv("CUELAB_SCREENSHOT_DIR");
    if (!dir.isEmpty()) {
        QTest::qWait(300);
        QVERIFY(w.grab().save(QString::fromLocal8Bit(dir) + QStringLiteral("/compare-window.png")));
    }

    // Closing the dock takes the ghosts away.
    dock->close();
    QTRY_VERIFY(w.tableView()->layers().count(QStringLiteral("compare")) == 0);
}

QTEST_MAIN(TestComparePanel)
#include "tst_comparepanel.moc"
