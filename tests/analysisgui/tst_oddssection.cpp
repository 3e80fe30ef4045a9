// The odds section of the Analysis dock (issue 25): presets fill the deviations, the current shot's
// odds come from the background and read "goes in N % (L–H %)" with the numbers of core/analysis,
// a map of odds streams in with its best cell marked and a readout under the mouse, a click on a
// cell loads its shot as one undo step, Cancel stops, and a change of the shot drops the odds.
// Saves a picture (odds-section.png in the build folder) for people to look at.

#include "analysis/AnalysisJob.h"
#include "analysis/AnalysisPanel.h"
#include "analysis/OddsMap.h"
#include "analysis/OddsSection.h"
#include "editor/Document.h"

#include "ShotOdds.h"
#include "ExamplePath.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QApplication>
#include <QLineEdit>
#include <QMouseEvent>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSpinBox>
#include <QUndoStack>
#include <QtTest>

using namespace cuelab;
using analysis::StrikeKey;

namespace {

bool waitForJob(OddsSection& section, int ms = 120000)
{
    QElapsedTimer timer;
    timer.start();
    while (section.job()->isRunning() && timer.elapsed() < ms) QTest::qWait(20);
    QTest::qWait(50);  // the last posted batches
    return !section.job()->isRunning();
}

struct Fixture {
    Document document;
    AnalysisPanel panel{&document};
    OddsSection* odds = nullptr;
    explicit Fixture(const char* example)
    {
        QString error;
        if (!document.load(examplePath(example), &error)) qFatal("%s", qPrintable(error));
        document.waitForResult();
        odds = panel.findChild<OddsSection*>();
        if (!odds) qFatal("the Analysis dock has no odds section");
        panel.resize(520, 1500);
        panel.show();
    }
};

}  // namespace

class TestOddsSection : public QObject {
    Q_OBJECT
private slots:
    void presetsFillTheDeviations();
    void oddsOfTheCurrentShot();
    void mapMarksTheBestCellAndLoadsOneUndoStep();
    void cancelStops();
    void changingTheShotDropsTheOdds();
};

void TestOddsSection::presetsFillTheDeviations()
{
    Fixture f("straight-shot.json");
    OddsSection& s = *f.odds;
    s.setPreset(0);  // FastFiz
    QCOMPARE(s.sigmaBox(StrikeKey::Heading)->value(), 0.185);
    QCOMPARE(s.sigmaBox(StrikeKey::Speed)->value(), 0.085);
    // 0.5 mm of a 28.575 mm ball: 0.0174978 R, shown to four decimals; the model keeps every digit.
    QCOMPARE(s.sigmaBox(StrikeKey::Side)->value(), 0.0175);
    QVERIFY(std::abs(s.noise()[StrikeKey::Side] - 0.0174978) < 1e-7);
    s.setPreset(1);  // club
    QCOMPARE(s.sigmaBox(StrikeKey::Heading)->value(), 0.3);
    // Editing a deviation makes the model the player's own.
    s.sigmaBox(StrikeKey::Heading)->setValue(0.25);
    QCOMPARE(s.presetBox()->currentIndex(), 3);
    QCOMPARE(s.noise()[StrikeKey::Heading], 0.25);
    QCOMPARE(s.noise()[StrikeKey::Speed], 0.12);
}

void TestOddsSection::oddsOfTheCurrentShot()
{
    Fixture f("half-ball-cut.json");
    OddsSection& s = *f.odds;
    QCOMPARE(f.panel.goalEdit()->text(), QStringLiteral("pot:1@pocket-tr,no-scratch"));
    s.setPreset(1);
    s.samplesBox()->setValue(1000);
    QSignalSpy progress(s.job(), &AnalysisJob::progressChanged);
    s.runOdds();
    QVERIFY(s.job()->isRunning());  // returned at once: the strikes run in the background
    QVERIFY(waitForJob(s));
    QVERIFY(progress.count() >= 1);
    const auto odds = s.currentOdds();
    QVERIFY(odds);
    static const QRegularExpression form(QStringLiteral("^goes in (\\d+) % \\((\\d+)–(\\d+) %\\)$"));
    const auto m = form.match(s.oddsText());
    QVERIFY2(m.hasMatch(), qPrintable(s.oddsText()));
    QCOMPARE(m.captured(1).toLong(), std::lround(odds->probability() * 100));
    QVERIFY(m.captured(2).toInt() <= m.captured(1).toInt() && m.captured(1).toInt() <= m.captured(3).toInt());
    // The numbers of core/analysis for the same request (the window stops once within ±1 %).
    analysis::SweepSpec spec;
    spec.base = f.document.setup();
    std::string error;
    spec.goal = *analysis::ResolvedGoal::resolve(std::get<analysis::Goal>(analysis::parseGoal("pot:1@pocket-tr,no-scratch")),
                                                spec.base, &error);
    analysis::OddsRequest request;
    request.noise = *analysis::presetNoise("club", 0.028575);
    request.samples = 1000;
    request.halfWidth = 0.01;
    const analysis::OddsResult direct = analysis::shotOdds(spec, {}, request, 1);
    QCOMPARE(odds->samples, direct.samples);
    QCOMPARE(odds->successes, direct.successes);
}

void TestOddsSection::mapMarksTheBestCellAndLoadsOneUndoStep()
{
    Fixture f("straight-shot.json");
    OddsSection& s = *f.odds;
    f.panel.goalEdit()->setText(QStringLiteral("pot:1@pocket-tr"));
    s.setPreset(0);
    s.xKeyBox()->setCurrentIndex(s.xKeyBox()->findData(QStringLiteral("shot.heading")));
    s.yKeyBox()->setCurrentIndex(s.yKeyBox()->findData(QStringLiteral("shot.side")));
    // The boxes name the keys in words with their units (issue 21, item 5), not as raw keys.
    QCOMPARE(s.xKeyBox()->currentText(), QStringLiteral("Heading (°)"));
    QCOMPARE(s.yKeyBox()->currentText(), QStringLiteral("Tip offset, side (R)"));
    s.rangeBox(0, 0)->setValue(39.0);
    s.rangeBox(0, 1)->setValue(41.0);
    s.rangeBox(1, 0)->setValue(-0.3);
    s.rangeBox(1, 1)->setValue(0.3);
    s.mapCellsBox()->setValue(5);
    s.mapSamplesBox()->setValue(60);
    s.runMap();
    QVERIFY(waitForJob(s));
    OddsMap* map = s.map();
    QCOMPARE(map->filled(), 25);
    QVERIFY(s.grab().save(QStringLiteral(CUELAB_BINARY_DIR "/odds-section.png")));
    // The best cell has the highest probability of all.
    const int best = map->bestCell();
    QVERIFY(best >= 0);
    for (int i = 0; i < 25; ++i) QVERIFY(map->oddsOf(i)->probability() <= map->oddsOf(best)->probability());
    // Along the straight line (heading 40°, the middle column) the pot is likely; 1° off it is not.
    QVERIFY(map->oddsOf(2 * 5 + 2)->probability() > map->oddsOf(2 * 5 + 0)->probability());
    // Hovering reads a cell out.
    const QPointF at = map->cellCentre(best);
    QMouseEvent move(QEvent::MouseMove, at, map->mapToGlobal(at), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(map, &move);
    QVERIFY2(map->readoutText().contains(QStringLiteral("shot.heading")) && map->readoutText().contains(QStringLiteral(" % (")),
             qPrintable(map->readoutText()));
    // A click on a cell that is not the current shot loads it as one undo step.
    int cell = best != 2 * 5 + 2 ? best : 0;
    const auto values = map->valuesOf(cell);
    const CueStrike before = *f.document.setup().shot;
    const int steps = f.document.undoStack()->count();
    QTest::mouseClick(map, Qt::LeftButton, {}, map->cellCentre(cell).toPoint());
    QCOMPARE(f.document.undoStack()->count(), steps + 1);
    QCOMPARE(f.document.setup().shot->headingDeg, values[0]);
    QCOMPARE(f.document.setup().shot->side, values[1]);
    QCOMPARE(map->filled(), 25);  // the loaded shot is one of the map's cells: the map stays
    f.document.undoStack()->undo();
    QCOMPARE(f.document.setup().shot->headingDeg, before.headingDeg);
    QCOMPARE(f.document.setup().shot->side, before.side);
}

void TestOddsSection::cancelStops()
{
    Fixture f("half-ball-cut.json");
    OddsSection& s = *f.odds;
    s.samplesBox()->setValue(1000000);
    s.sigmaBox(StrikeKey::Heading)->setValue(1.0);  // a wide scatter: no early stop
    s.runOdds();
    QVERIFY(s.job()->isRunning());
    s.cancel();  // at once: the whole run takes a fraction of a second
    QVERIFY(!s.job()->isRunning());
    QCOMPARE(s.statusText(), QStringLiteral("Cancelled."));
    QVERIFY(!s.currentOdds());
    QVERIFY(s.oddsText().isEmpty());
}

void TestOddsSection::changingTheShotDropsTheOdds()
{
    Fixture f("straight-shot.json");
    OddsSection& s = *f.odds;
    f.panel.goalEdit()->setText(QStringLiteral("pot:1@pocket-tr"));
    s.samplesBox()->setValue(300);
    s.runOdds();
    QVERIFY(waitForJob(s));
    QVERIFY(s.currentOdds());
    Setup changed = f.document.setup();
    changed.shot->speed = 1.0;
    QVERIFY(f.document.edit(QStringLiteral("speed"), changed));
    QVERIFY(!s.currentOdds());
    QCOMPARE(s.oddsText(), QStringLiteral("the shot changed: press Odds"));
}

QTEST_MAIN(TestOddsSection)
#include "tst_oddssection.moc"
