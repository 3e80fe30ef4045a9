// "Find shots" in the Analysis dock (issue 42): the dock's goal and the odds section's noise go to
// core/solve on background threads; the shots come back listed best first with their odds and
// route, the same as core/solve finds for that input; a click on a listed shot loads its strike as
// one undo step; Cancel stops; a change of the setup makes the list stale. Saves a picture
// (shot-finder.png in the build folder) for people to look at.

#include "analysis/AnalysisJob.h"
#include "analysis/AnalysisPanel.h"
#include "analysis/OddsSection.h"
#include "analysis/ShotFinderSection.h"
#include "editor/Document.h"

#include "ExamplePath.h"

#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QUndoStack>
#include <QtTest>

using namespace cuelab;

namespace {

bool waitForJob(ShotFinderSection& section, int ms = 120000)
{
    QElapsedTimer timer;
    timer.start();
    while (section.job()->isRunning() && timer.elapsed() < ms) QTest::qWait(20);
    QTest::qWait(50);  // the posted result
    return !section.job()->isRunning();
}

struct Fixture {
    Document document;
    AnalysisPanel panel{&document};
    ShotFinderSection* finder = nullptr;
    OddsSection* odds = nullptr;
    explicit Fixture(const char* example)
    {
        QString error;
        if (!document.load(examplePath(example), &error)) qFatal("%s", qPrintable(error));
        document.waitForResult();
        finder = panel.findChild<ShotFinderSection*>();
        odds = panel.findChild<OddsSection*>();
        if (!finder || !odds) qFatal("the Analysis dock has no shot finder or odds section");
        panel.resize(520, 1800);
        panel.show();
    }
};

}  // namespace

class TestShotFinder : public QObject {
    Q_OBJECT
private slots:
    void findsListsAndLoadsOneUndoStep();
    void pickingMakesTheGoal();
    void badGoalIsSaid();
    void cancelStops();
};

void TestShotFinder::findsListsAndLoadsOneUndoStep()
{
    Fixture f("straight-shot.json");
    f.panel.goalEdit()->setText(QStringLiteral("pot:1@pocket-tr"));
    f.odds->setPreset(2);  // a professional
    f.finder->topBox()->setValue(2);
    f.finder->find();
    QVERIFY(waitForJob(*f.finder));
    const auto& shots = f.finder->shots();
    QVERIFY(!shots.empty() && shots.size() <= 2);
    QCOMPARE(f.finder->list()->count(), static_cast<int>(shots.size()));
    QCOMPARE(shots.front().route, std::string("direct"));
    QVERIFY2(f.finder->list()->item(0)->text().startsWith(QStringLiteral("1. direct: ")),
             qPrintable(f.finder->list()->item(0)->text()));
    QVERIFY(f.finder->statusText().contains(QStringLiteral("simulations")));
    QVERIFY(f.finder->grab().save(QStringLiteral(CUELAB_BINARY_DIR "/shot-finder.png")));

    // The chosen (first) shot's paths for the table: the cue ball's from its place, the 1's.
    const ViewLayer layer = f.finder->ghostLayer();
    QCOMPARE(layer.polylines.size(), std::size_t{2});
    const Vec2 cue = f.document.setup().balls[0].state.position;
    QVERIFY((layer.polylines[0].points.front().head<2>() - cue).norm() < 1e-12);
    QVERIFY(layer.polylines[0].points.size() > 10);
    QSignalSpy layerChanged(f.finder, &ShotFinderSection::ghostLayerChanged);
    if (f.finder->list()->count() > 1) {
        f.finder->list()->setCurrentRow(1);
        QCOMPARE(layerChanged.count(), 1);
    }

    // A click on the first shot loads its strike: one undo step, undone as one.
    const CueStrike before = *f.document.setup().shot;
    const int steps = f.document.undoStack()->count();
    QVERIFY(f.finder->loadShot(0));
    QCOMPARE(f.document.undoStack()->count(), steps + 1);
    QCOMPARE(f.document.setup().shot->headingDeg, shots.front().strike[0]);
    QCOMPARE(f.document.setup().shot->speed, shots.front().strike[1]);
    QCOMPARE(f.document.setup().shot->height, shots.front().strike[3]);
    QVERIFY(f.finder->list()->isEnabled());  // its own load does not make the list stale
    f.document.undoStack()->undo();
    QCOMPARE(f.document.setup().shot->headingDeg, before.headingDeg);

    // The undo changed the setup behind the list's back? No: it restored the solved setup, but the
    // list cannot know; any change after a find makes it stale.
    QVERIFY(!f.finder->list()->isEnabled());
    QVERIFY(f.finder->ghostLayer().polylines.empty());
    QVERIFY(!f.finder->loadShot(0));
    QVERIFY(f.finder->statusText().contains(QStringLiteral("find again")));
}

void TestShotFinder::pickingMakesTheGoal()
{
    Fixture f("straight-shot.json");
    f.panel.goalEdit()->setText(QStringLiteral("pot:1"));
    f.finder->pickButton()->setChecked(true);
    QVERIFY(f.finder->picking());
    f.finder->pickBall(0);  // the cue ball: not a ball to pot
    QVERIFY(f.finder->statusText().contains(QStringLiteral("struck ball")));
    QCOMPARE(f.panel.goalEdit()->text(), QStringLiteral("pot:1"));
    f.finder->pickBall(1);
    QCOMPARE(f.panel.goalEdit()->text(), QStringLiteral("pot:1,no-scratch"));
    f.finder->pickPocket(5);  // pocket-tr (pockets: bl, b, br, tl, t, tr)
    QCOMPARE(f.panel.goalEdit()->text(), QStringLiteral("pot:1@pocket-tr,no-scratch"));
    // A zone dragged from its top-right corner to its bottom-left one.
    QSignalSpy layerChanged(f.finder, &ShotFinderSection::ghostLayerChanged);
    f.finder->previewZone(Vec2(1.7, 0.58), Vec2(1.5, 0.4));
    QCOMPARE(layerChanged.count(), 1);
    f.finder->pickZone(Vec2(1.7, 0.58), Vec2(1.46, 0.34));
    QCOMPARE(f.panel.goalEdit()->text(), QStringLiteral("pot:1@pocket-tr,no-scratch,in:cue@1.460:0.340:1.700:0.580"));
    const ViewLayer layer = f.finder->ghostLayer();
    QCOMPARE(layer.polylines.size(), std::size_t{1});
    QVERIFY(layer.polylines[0].closed);
    QCOMPARE(layer.polylines[0].points.size(), std::size_t{4});
    QCOMPARE(layer.polylines[0].points[0].x(), 1.46);
    QCOMPARE(layer.polylines[0].points[2].y(), 0.58);
    // Picking again starts afresh; off, the zone is not drawn.
    f.finder->pickButton()->setChecked(false);
    QVERIFY(f.finder->ghostLayer().polylines.empty());
}

void TestShotFinder::badGoalIsSaid()
{
    Fixture f("straight-shot.json");
    f.panel.goalEdit()->setText(QStringLiteral("pot:9"));
    f.finder->find();
    QVERIFY(!f.finder->job()->isRunning());
    QVERIFY2(f.finder->statusText().contains(QStringLiteral("\"9\"")), qPrintable(f.finder->statusText()));
    f.panel.goalEdit()->setText(QStringLiteral("pot:1,in:cue@3:2:4:3"));
    f.finder->find();
    QVERIFY2(f.finder->statusText().contains(QStringLiteral("off the table")), qPrintable(f.finder->statusText()));
}

void TestShotFinder::cancelStops()
{
    Fixture f("straight-shot.json");
    f.panel.goalEdit()->setText(QStringLiteral("pot:1@pocket-tr,no-scratch"));
    f.finder->find();
    QVERIFY(f.finder->job()->isRunning());
    f.finder->cancel();
    QVERIFY(waitForJob(*f.finder, 10000));
    QCOMPARE(f.finder->list()->count(), 0);
    QCOMPARE(f.finder->statusText(), QStringLiteral("Cancelled."));
}

QTEST_MAIN(TestShotFinder)
#include "tst_shotfinder.moc"
