// The shot finder's goal from clicks in the window (issue 42): with "Pick on the table" checked, a
// click on a ball in the table view picks the ball to pot, a click at a pocket its pocket, and a
// drag on the cloth the zone where the cue ball should stop; the dock's goal says so. Unchecked,
// the same clicks are the view's own again (they select; the goal stays).

#include "MainWindow.h"
#include "analysis/AnalysisPanel.h"
#include "analysis/OutcomeMap.h"
#include "analysis/ShotFinderSection.h"
#include "editor/Document.h"
#include "editor/Playback.h"
#include "view/TableView.h"

#include "Table.h"

#include <QDockWidget>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QScrollArea>
#include <QTabWidget>
#include <QScrollBar>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

using namespace cuelab;

class TestShotFinderWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings_.path());
        QSettings().clear();
        QSettings().setValue(QStringLiteral("help/firstStartTipSeen"), true);  // the tip would cover the view
    }
    void clicksMakeTheGoal();
    void mapTipOffsetsShowsTheMap();

private:
    QTemporaryDir settings_;
};

void TestShotFinderWindow::clicksMakeTheGoal()
{
    MainWindow window;
    window.resize(1600, 1000);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openFile(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/straight-shot.json")));
    window.document()->waitForResult();
    auto* dock = window.findChild<QDockWidget*>(QStringLiteral("AnalysisDock"));
    QVERIFY(dock);
    dock->show();
    dock->raise();
    QTest::qWait(200);  // the view laid out beside the dock, the scene of the result in it
    auto* panel = window.findChild<AnalysisPanel*>();
    auto* finder = window.findChild<ShotFinderSection*>();
    QVERIFY(panel && finder);
    TableView* view = window.tableView();
    const double r = window.document()->setup().balls[1].radius;
    const auto at = [&](double x, double y, double z) {
        const auto p = view->widgetPointOf(QVector3D(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)));
        if (!p) qFatal("(%g, %g) is not in the view", x, y);
        return p->toPoint();
    };

    panel->goalEdit()->setText(QStringLiteral("pot:1"));
    // Not picking: a click on the 1 is the view's (a selection); the goal stays.
    QTest::mouseClick(view, Qt::LeftButton, {}, at(1.93, 0.7586, r));
    QCOMPARE(panel->goalEdit()->text(), QStringLiteral("pot:1"));

    finder->pickButton()->setChecked(true);
    QTest::mouseClick(view, Qt::LeftButton, {}, at(1.93, 0.7586, r));
    QCOMPARE(panel->goalEdit()->text(), QStringLiteral("pot:1,no-scratch"));
    const Table table = makeTable(window.document()->setup().table);
    const Vec2 topLeft = table.pockets[3].centre;  // pocket-tl
    QTest::mouseClick(view, Qt::LeftButton, {}, at(topLeft.x(), topLeft.y(), 0.0));
    QCOMPARE(panel->goalEdit()->text(), QStringLiteral("pot:1@pocket-tl,no-scratch"));
    // A drag on the cloth: the zone, whatever the pixels round it to (within a few mm).
    const QPoint from = at(1.0, 0.3, 0.0), to = at(1.4, 0.6, 0.0);
    QTest::mousePress(view, Qt::LeftButton, {}, from);
    QTest::mouseMove(view, (from + to) / 2);
    QTest::mouseMove(view, to);
    QTest::mouseRelease(view, Qt::LeftButton, {}, to);
    const QString goal = panel->goalEdit()->text();
    const QRegularExpressionMatch m =
        QRegularExpression(QStringLiteral("^pot:1@pocket-tl,no-scratch,in:cue@([0-9.]+):([0-9.]+):([0-9.]+):([0-9.]+)$")).match(goal);
    QVERIFY2(m.hasMatch(), qPrintable(goal));
    QVERIFY(std::abs(m.captured(1).toDouble() - 1.0) < 0.01);
    QVERIFY(std::abs(m.captured(2).toDouble() - 0.3) < 0.01);
    QVERIFY(std::abs(m.captured(3).toDouble() - 1.4) < 0.01);
    QVERIFY(std::abs(m.captured(4).toDouble() - 0.6) < 0.01);
    QVERIFY(view->layers().count(QStringLiteral("shot-finder")) == 1);  // the zone drawn
    // No ball moved: the picks took the clicks.
    QCOMPARE(window.document()->setup().balls[1].state.position.x(), 1.93);

    finder->pickButton()->setChecked(false);
    QVERIFY(view->layers().count(QStringLiteral("shot-finder")) == 0);
}

// Analysis > Map tip offsets with the Find shots tab raised: the map's tab is raised and the map is
// in view within the dock (issue 44: it opened above the visible part of a dock that had to scroll;
// the sections are tabs now, and the dock needs no scrolling at 1280x800).
void TestShotFinderWindow::mapTipOffsetsShowsTheMap()
{
    MainWindow window;
    window.resize(1280, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openFile(QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/straight-shot.json")));
    window.document()->waitForResult();
    auto* dock = window.findChild<QDockWidget*>(QStringLiteral("AnalysisDock"));
    QVERIFY(dock);
    dock->show();
    dock->raise();
    QTest::qWait(200);
    auto* panel = window.findChild<AnalysisPanel*>();
    QVERIFY(panel);
    if (auto* scroller = qobject_cast<QScrollArea*>(dock->widget())) QCOMPARE(scroller->verticalScrollBar()->maximum(), 0);
    panel->showSection(AnalysisPanel::FinderPage);
    QCoreApplication::processEvents();
    QVERIFY(!panel->map()->isVisible());
    const auto mapShown = [&] {
        if (!panel->map()->isVisible()) return false;
        const QRect map(panel->map()->mapTo(dock, QPoint(0, 0)), panel->map()->size());
        return dock->rect().intersected(map).height() >= std::min(map.height(), dock->height()) / 2;
    };
    QAction* map = nullptr;
    for (QAction* a : window.findChildren<QAction*>())
        if (a->shortcut() == QKeySequence(QStringLiteral("Ctrl+Alt+M"))) map = a;
    QVERIFY(map);
    map->trigger();
    QCOMPARE(panel->sections()->currentIndex(), static_cast<int>(AnalysisPanel::MapPage));
    QTRY_VERIFY(mapShown());
    panel->cancel();
}

QTEST_MAIN(TestShotFinderWindow)
#include "tst_shotfinderwindow.moc"
