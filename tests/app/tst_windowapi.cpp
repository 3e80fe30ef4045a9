// The window's extension API, through which features add docks and menu entries (MainWindow.h),
// the shared Selection, and Help > Keyboard and Mouse, which lists every shortcut of the menus.

#include "DockLayout.h"
#include "MainWindow.h"
#include "ShortcutsDialog.h"

#include "editor/Selection.h"

#include <QAbstractButton>
#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QtTest>

using namespace cuelab;

namespace {

QMenu* topMenu(QMenuBar* bar, const QString& title)
{
    for (QAction* a : bar->actions())
        if (a->menu() && a->text().remove(QLatin1Char('&')) == title) return a->menu();
    return nullptr;
}

}  // namespace

class WindowApiTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void addPanelListsTheDockInViewPanels()
    {
        MainWindow window;
        const qsizetype before = window.panels().size();
        QDockWidget* dock = window.addPanel(new QLabel(QStringLiteral("hello")), QStringLiteral("Probe"),
                                            QStringLiteral("ProbeDock"), {Qt::RightDockWidgetArea, QStringLiteral("InspectorDock")});
        QCOMPARE(window.panels().size(), before + 1);
        QCOMPARE(dock->objectName(), QStringLiteral("ProbeDock"));
        QCOMPARE(window.dockWidgetArea(dock), Qt::RightDockWidgetArea);
        // Tabified with the Inspector, as asked.
        QDockWidget* inspector = window.findChild<QDockWidget*>(QStringLiteral("InspectorDock"));
        QVERIFY(inspector);
        QVERIFY(window.tabifiedDockWidgets(inspector).contains(dock));
        // Listed in View > Panels, where its toggle hides and shows it.
        QMenu* view = topMenu(window.menuBar(), QStringLiteral("View"));
        QVERIFY(view);
        QMenu* panels = nullptr;
        for (QAction* a : view->actions())
            if (a->menu() && a->text().remove(QLatin1Char('&')) == QLatin1String("Panels")) panels = a->menu();
        QVERIFY(panels);
        QVERIFY(panels->actions().contains(dock->toggleViewAction()));
    }

    void exportMenuSitsInFileBeforeQuit()
    {
        MainWindow window;
        QMenu* file = window.menu(WindowMenu::File);
        QMenu* exportMenu = window.menu(WindowMenu::Export);
        QVERIFY(exportMenu);
        QCOMPARE(window.menu(WindowMenu::Export), exportMenu);  // made once
        const QList<QAction*> actions = file->actions();
        const qsizetype exportAt = actions.indexOf(exportMenu->menuAction());
        qsizetype quitAt = -1;
        for (qsizetype i = 0; i < actions.size(); ++i)
            if (actions[i]->text().remove(QLatin1Char('&')) == QLatin1String("Quit")) quitAt = i;
        QVERIFY(exportAt >= 0);
        QVERIFY2(exportAt < quitAt, "Export comes before Quit");
    }

    void analysisMenuAppearsWhenUsed()
    {
        MainWindow window;
        QMenu* analysis = window.menu(WindowMenu::Analysis);
        QVERIFY(analysis);
        QVERIFY(analysis->menuAction()->isVisible());
        QVERIFY(window.menu(WindowMenu::Help) != nullptr);
        QVERIFY(window.menu(WindowMenu::Playback) != nullptr);
    }

    // Shrinking the window to 800x600 keeps every side dock usable, and growing it back gives the
    // docks their share again instead of handing every pixel to the table view.
    void docksSurviveResizing()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTest::qWait(100);
        QDockWidget* balls = window.findChild<QDockWidget*>(QStringLiteral("BallsDock"));
        QDockWidget* events = window.findChild<QDockWidget*>(QStringLiteral("EventsDock"));
        QVERIFY(balls && events);
        const int ballsBefore = balls->width();
        const int eventsBefore = events->width();
        QVERIFY2(ballsBefore >= DockLayout::kMinimumDockWidth, qPrintable(QString::number(ballsBefore)));

        window.resize(800, 600);
        // Every panel's minimum lets the window be that small (scroll areas, a compact transport).
        QTRY_VERIFY2_WITH_TIMEOUT(window.width() == 800 && window.height() == 600,
                                  qPrintable(QStringLiteral("%1x%2").arg(window.width()).arg(window.height())), 3000);
        QTest::qWait(200);
        QVERIFY2(balls->width() >= DockLayout::kMinimumDockWidth, qPrintable(QString::number(balls->width())));
        QVERIFY2(events->width() >= DockLayout::kMinimumDockWidth, qPrintable(QString::number(events->width())));

        window.resize(1600, 1000);
        // The X server confirms the new size when it will: wait for it (up to 3 s), not a fixed time.
        QTRY_VERIFY_WITH_TIMEOUT(window.width() == 1600, 3000);
        QTRY_VERIFY2_WITH_TIMEOUT(std::abs(balls->width() - ballsBefore) <= 0.05 * ballsBefore,
                                  qPrintable(QStringLiteral("%1 then %2").arg(ballsBefore).arg(balls->width())), 3000);
        QTRY_VERIFY2_WITH_TIMEOUT(std::abs(events->width() - eventsBefore) <= 0.05 * eventsBefore,
                                  qPrintable(QStringLiteral("%1 then %2").arg(eventsBefore).arg(events->width())), 3000);

        // A separator dragged by the user sets the share that later resizes keep.
        QTest::qWait(200);
        window.resizeDocks({balls}, {520}, Qt::Horizontal);
        QTest::qWait(50);
        QCOMPARE(balls->width(), 520);
        QTest::mouseRelease(&window, Qt::LeftButton, {}, QPoint(balls->width() + 2, window.height() / 2));
        QTest::qWait(50);
        const double share = window.dockLayout()->leftShare();
        QVERIFY2(std::abs(share - balls->width() / 1600.0) < 0.01, qPrintable(QString::number(share)));
        QVERIFY2(share > 0.3, qPrintable(QString::number(share)));
        window.resize(1200, 800);
        QTRY_VERIFY_WITH_TIMEOUT(window.width() == 1200, 3000);
        QTRY_VERIFY2_WITH_TIMEOUT(std::abs(balls->width() - share * 1200) <= 0.05 * share * 1200,
                                  qPrintable(QString::number(balls->width())), 3000);
    }

    void resetLayoutBringsPanelsBack()
    {
        MainWindow window;
        window.resize(1400, 900);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QDockWidget* events = window.findChild<QDockWidget*>(QStringLiteral("EventsDock"));
        QDockWidget* shot = window.findChild<QDockWidget*>(QStringLiteral("ShotDock"));
        events->setFloating(true);
        shot->hide();
        window.resetLayout();
        QTest::qWait(100);
        QVERIFY(!events->isFloating());
        QCOMPARE(window.dockWidgetArea(events), Qt::RightDockWidgetArea);
        QVERIFY(!shot->isHidden());
        QCOMPARE(window.dockWidgetArea(shot), Qt::LeftDockWidgetArea);
    }

    void unusableRememberedLayoutIsRefused()
    {
        MainWindow window;
        // Shares that would leave the table view no room are refused; the defaults stay.
        QVERIFY(!window.dockLayout()->restore({}, QVariantList{0.6, 0.5}));
        QCOMPARE(window.dockLayout()->leftShare(), DockLayout::kDefaultLeftShare);
        QVERIFY(!window.dockLayout()->restore(QByteArray("not a state"), QVariantList{0.2, 0.2}));
        QVERIFY(window.dockLayout()->restore({}, QVariantList{0.2, 0.25}));
        QCOMPARE(window.dockLayout()->rightShare(), 0.25);
    }

    void firstStartTipShowsOnce()
    {
        QSettings().remove(QStringLiteral("help/firstStartTipSeen"));
        {
            MainWindow first;
            auto* tip = first.findChild<QWidget*>(QStringLiteral("firstStartTip"));
            QVERIFY(tip);
            QVERIFY(tip->isVisibleTo(&first));
            auto* close = first.findChild<QAbstractButton*>(QStringLiteral("firstStartTipClose"));
            QVERIFY(close);
            close->click();
            QVERIFY(!tip->isVisibleTo(&first));
        }
        MainWindow second;
        QVERIFY(!second.findChild<QWidget*>(QStringLiteral("firstStartTip"))->isVisibleTo(&second));
    }

    void selectionRules()
    {
        Selection s;
        QSignalSpy balls(&s, &Selection::ballChanged);
        QSignalSpy events(&s, &Selection::eventChanged);
        s.selectBall(2);
        QCOMPARE(s.ball(), 2);
        QCOMPARE(s.subject(), Selection::Subject::Ball);
        s.selectBall(2);
        QCOMPARE(balls.size(), 1);  // no change, no signal
        s.selectEvent(5);
        QCOMPARE(s.event(), 5);
        QCOMPARE(s.ball(), 2);  // the ball stays marked
        QCOMPARE(s.subject(), Selection::Subject::Event);
        s.selectEvent(5);
        QCOMPARE(events.size(), 2);  // choosing the event again asks to go there again
        s.selectBall(1);
        QCOMPARE(s.event(), -1);  // a ball clears the event
        QCOMPARE(s.subject(), Selection::Subject::Ball);
        s.clear();
        QCOMPARE(s.ball(), -1);
        QCOMPARE(s.subject(), Selection::Subject::None);
    }

    void shortcutsListEveryMenuShortcut()
    {
        MainWindow window;
        const QList<ShortcutsDialog::Row> rows = ShortcutsDialog::keyboardRows(window.menuBar());
        const auto has = [&rows](const QString& what, const QKeySequence& keys) {
            for (const ShortcutsDialog::Row& r : rows)
                if (r.what == what && r.how.contains(keys.toString(QKeySequence::NativeText))) return true;
            return false;
        };
        QVERIFY(has(QStringLiteral("Undo"), QKeySequence::Undo));
        QVERIFY(has(QStringLiteral("Open"), QKeySequence::Open));
        QVERIFY(has(QStringLiteral("Top"), QKeySequence(Qt::CTRL | Qt::Key_1)));
        // Every action with a shortcut anywhere in the menus is listed.
        qsizetype withShortcut = 0;
        std::function<void(const QMenu*)> count = [&](const QMenu* m) {
            for (QAction* a : m->actions()) {
                if (a->menu()) count(a->menu());
                else if (!a->isSeparator() && !a->shortcuts().isEmpty()) ++withShortcut;
            }
        };
        for (QAction* a : window.menuBar()->actions())
            if (a->menu()) count(a->menu());
        QCOMPARE(rows.size(), withShortcut);
        QVERIFY(!ShortcutsDialog::mouseRows().isEmpty());
    }
};

QTEST_MAIN(WindowApiTest)
#include "tst_windowapi.moc"
