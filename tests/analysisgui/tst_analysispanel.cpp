// The Analysis dock: a tip-offset map streams in and colours its cells, a click on a cell loads that
// shot into the editor as one undo step (and Undo brings the old shot back), the tolerance bars
// find a window around the current heading, cancel stops, and results are dropped when the setup
// changes. Saves a picture of the dock (analysis-dock.png in the build folder) for people to look at.

#include "analysis/AnalysisJob.h"
#include "analysis/AnalysisPanel.h"
#include "analysis/OutcomeMap.h"
#include "analysis/ToleranceBar.h"
#include "editor/Document.h"
#include "ExamplePath.h"

#include <QComboBox>
#include <QTableWidget>
#include <QLineEdit>
#include <QSignalSpy>
#include <QSpinBox>
#include <QUndoStack>
#include <QLabel>
#include <QTableWidget>
#include <QTabWidget>
#include <QtTest>

using namespace cuelab;
using analysis::ShotClass;

namespace {

bool waitForJob(AnalysisPanel& panel, int ms = 120000)
{
    QElapsedTimer timer;
    timer.start();
    while (panel.job()->isRunning() && timer.elapsed() < ms) QTest::qWait(20);
    QTest::qWait(50);  // the last posted batches
    return !panel.job()->isRunning();
}

struct Fixture {
    Document document;
    AnalysisPanel panel{&document};
    Fixture(const char* example)
    {
        QString error;
        if (!document.load(examplePath(example), &error)) qFatal("%s", qPrintable(error));
        document.waitForResult();
        panel.resize(480, 900);
        panel.show();
    }
};

}  // namespace

class TestAnalysisPanel : public QObject {
    Q_OBJECT
private slots:
    void goalComesFromTheShot();
    void mapStreamsAndClickLoadsOneUndoStep();
    void toleranceBarsFindTheWindow();
    void cancelStops();
    void setupChangeDropsResults();
    void twoParameterMap();
    void sectionsAreTabs();
};

void TestAnalysisPanel::goalComesFromTheShot()
{
    Fixture f("half-ball-cut.json");
    QCOMPARE(f.panel.goalEdit()->text(), QStringLiteral("pot:1@pocket-tr,no-scratch"));
}

void TestAnalysisPanel::mapStreamsAndClickLoadsOneUndoStep()
{
    Fixture f("half-ball-cut.json");
    f.panel.mapCells()->setValue(21);
    QSignalSpy progress(f.panel.job(), &AnalysisJob::progressChanged);
    f.panel.runMap();
    QVERIFY(f.panel.job()->isRunning());  // the call returned at once: the work is in the background
    QVERIFY(waitForJob(f.panel));
    QVERIFY(progress.count() >= 1);
    OutcomeMap* map = f.panel.map();
    QCOMPARE(map->filled(), 21 * 21);
    const auto counts = map->counts();
    QVERIFY(counts[static_cast<std::size_t>(ShotClass::GoalMet)] > 0);
    QVERIFY(counts[static_cast<std::size_t>(ShotClass::Outside)] > 0);
    QVERIFY(counts[static_cast<std::size_t>(ShotClass::GoalMet)] + counts[static_cast<std::size_t>(ShotClass::Outside)] < 21 * 21);

    const QString picture = QStringLiteral(CUELAB_BINARY_DIR "/analysis-dock.png");
    QVERIFY(f.panel.grab().save(picture));

    // A cell that meets the goal and is not the current shot: click it.
    int cell = -1;
    for (int i = 0; i < 21 * 21 && cell < 0; ++i) {
        const auto v = map->valuesOf(i);
        if (map->classOf(i) == ShotClass::GoalMet && std::abs(v[0]) > 0.1) cell = i;
    }
    QVERIFY(cell >= 0);
    const auto values = map->valuesOf(cell);
    const CueStrike before = *f.document.setup().shot;
    const int steps = f.document.undoStack()->count();
    QTest::mouseClick(map, Qt::LeftButton, {}, map->cellCentre(cell).toPoint());
    QCOMPARE(f.document.undoStack()->count(), steps + 1);
    QCOMPARE(f.document.setup().shot->side, values[0]);
    QCOMPARE(f.document.setup().shot->height, values[1]);
    QCOMPARE(f.document.setup().shot->speed, before.speed);
    // The map stays (the new setup is one of its cells) and its cross moved.
    QCOMPARE(map->filled(), 21 * 21);
    f.document.undoStack()->undo();
    QCOMPARE(f.document.setup().shot->side, before.side);
    QCOMPARE(f.document.setup().shot->height, before.height);
    QCOMPARE(f.document.undoStack()->index(), steps);
}

void TestAnalysisPanel::toleranceBarsFindTheWindow()
{
    Fixture f("straight-shot.json");
    f.panel.goalEdit()->setText(QStringLiteral("pot:1@pocket-tr"));
    f.panel.runTolerance();
    QVERIFY(waitForJob(f.panel));
    const auto& bars = f.panel.bars();
    QCOMPARE(bars.size(), std::size_t(5));
    for (ToleranceBar* bar : bars) QVERIFY2(bar->hasScan(), qPrintable(bar->text()));
    const auto& heading = *bars[0]->scan();
    QCOMPARE(heading.key, std::string("shot.heading"));
    QVERIFY(heading.found && heading.currentMet);
    QVERIFY(heading.low < 40.005 && heading.high > 40.005 && heading.width() < 1.0);
    QVERIFY2(bars[0]->text().contains(QStringLiteral("from ")) && bars[0]->text().contains(QStringLiteral("±")),
             qPrintable(bars[0]->text()));
    // The goal is said once, above the bars, not on every bar.
    auto* goal = f.panel.findChild<QLabel*>(QStringLiteral("toleranceGoal"));
    QVERIFY(goal && goal->text().startsWith(QStringLiteral("Goal: ")));
    for (ToleranceBar* bar : bars) QVERIFY2(!bar->text().contains(QStringLiteral("pot ")), qPrintable(bar->text()));
    // The windows as a number table: from, to, width, and what lies beyond each end.
    QTableWidget* table = f.panel.toleranceTable();
    QVERIFY(table->isVisibleTo(&f.panel));
    QCOMPARE(table->rowCount(), 5);
    QCOMPARE(table->item(0, 0)->text(), QStringLiteral("Heading"));
    QCOMPARE(table->item(0, 1)->text(), QString::number(heading.low, 'f', 2) + QStringLiteral("°"));
    QCOMPARE(table->item(0, 2)->text(), QString::number(heading.high, 'f', 2) + QStringLiteral("°"));
    QCOMPARE(table->item(0, 3)->text(), QString::number(heading.width(), 'f', 2) + QStringLiteral("°"));
    // The heading's window lies inside the ±2° scan: the pot fails beyond both ends.
    QVERIFY(!heading.lowAtScanEdge && !heading.highAtScanEdge);
    QCOMPARE(table->item(0, 4)->text(), QStringLiteral("fails"));
    QCOMPARE(table->item(0, 5)->text(), QStringLiteral("fails"));
    for (int row = 0; row < table->rowCount(); ++row) {
        const auto& scan = *bars[std::size_t(row)]->scan();
        if (!scan.found) continue;
        QCOMPARE(table->item(row, 4)->text(), scan.lowAtScanEdge ? QStringLiteral("scan's edge") : QStringLiteral("fails"));
        QCOMPARE(table->item(row, 5)->text(), scan.highAtScanEdge ? QStringLiteral("scan's edge") : QStringLiteral("fails"));
    }
    qInfo("%s", qPrintable(f.panel.statusText()));
    QVERIFY(f.panel.grab().save(QStringLiteral(CUELAB_BINARY_DIR "/analysis-tolerance.png")));
}

void TestAnalysisPanel::cancelStops()
{
    Fixture f("half-ball-cut.json");
    f.panel.mapCells()->setValue(301);
    f.panel.runMap();
    QTest::qWait(100);
    f.panel.cancel();
    QVERIFY(!f.panel.job()->isRunning());
    const int filled = f.panel.map()->filled();
    QVERIFY(filled < 301 * 301);
    QTest::qWait(200);
    QCOMPARE(f.panel.map()->filled(), filled);  // nothing arrives after cancel
}

void TestAnalysisPanel::setupChangeDropsResults()
{
    Fixture f("straight-shot.json");
    f.panel.mapCells()->setValue(9);
    f.panel.runMap();
    QVERIFY(waitForJob(f.panel));
    QVERIFY(!f.panel.map()->isEmpty());
    QVERIFY(f.document.moveBall(1, Vec2(1.9, 0.7)));
    f.document.endMerge();
    QVERIFY(f.panel.map()->isEmpty());
    // A running job is stopped by an edit and nothing of it lands.
    f.panel.mapCells()->setValue(201);
    f.panel.runMap();
    QTest::qWait(50);
    QVERIFY(f.document.moveBall(1, Vec2(1.92, 0.72)));
    QVERIFY(!f.panel.job()->isRunning());
    QTest::qWait(200);
    QVERIFY(f.panel.map()->isEmpty());
}

void TestAnalysisPanel::twoParameterMap()
{
    Fixture f("straight-shot.json");
    f.panel.mapMode()->setCurrentIndex(AnalysisPanel::TwoParameters);
    f.panel.mapCells()->setValue(7);
    f.panel.runMap();
    QVERIFY(waitForJob(f.panel));
    QCOMPARE(f.panel.map()->filled(), 49);
    QVERIFY(f.panel.map()->counts()[static_cast<std::size_t>(ShotClass::Outside)] == 0);
}

void TestAnalysisPanel::sectionsAreTabs()
{
    // The four sections are tabs under the shared goal (issue 44's review: stacked, they needed
    // scrolling even at 2560x1440): the panel's least height fits the Coach layout's right column at
    // 1280x800 with room to spare, and the scan, the map and the finder raise their own tab.
    Fixture f("half-ball-cut.json");
    QTabWidget* tabs = f.panel.sections();
    QVERIFY(tabs);
    QCOMPARE(tabs->count(), 4);
    const int least = f.panel.minimumSizeHint().height();
    qInfo() << "least height" << least << "pages" << tabs->widget(0)->minimumSizeHint().height() << tabs->widget(1)->minimumSizeHint().height()
            << tabs->widget(2)->minimumSizeHint().height() << tabs->widget(3)->minimumSizeHint().height();
    QVERIFY2(least <= 560, qPrintable(QString::number(least)));
    f.panel.showSection(AnalysisPanel::OddsPage);
    QVERIFY(!f.panel.map()->isVisibleTo(&f.panel));
    f.panel.mapMode()->setCurrentIndex(AnalysisPanel::TipOffsetDisk);
    f.panel.mapCells()->setValue(5);
    f.panel.runMap();
    QCOMPARE(tabs->currentIndex(), static_cast<int>(AnalysisPanel::MapPage));
    QVERIFY(f.panel.map()->isVisibleTo(&f.panel));
    QVERIFY(waitForJob(f.panel));
    f.panel.runTolerance();
    QCOMPARE(tabs->currentIndex(), static_cast<int>(AnalysisPanel::TolerancePage));
    QVERIFY(waitForJob(f.panel));
}

QTEST_MAIN(TestAnalysisPanel)
#include "tst_analysispanel.moc"
