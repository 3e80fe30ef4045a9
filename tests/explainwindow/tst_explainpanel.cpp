// The Explain dock follows the selected event and the transport, shows the derivation with its
// polynomial and roots; the Lesson dock shows an opened example's lesson at once and its edits are
// undo steps; File > Export > Explanation writes HTML and Markdown atomically. The selected
// collision's contact, normal, impulse and momenta are arrows in the table view, built from the
// simulator's own event data and following the selection. A screenshot of the Explain dock on the
// half-ball cut goes to the build folder (explain-dock.png).

#include "MainWindow.h"
#include "editor/Document.h"
#include "editor/Playback.h"
#include "editor/Selection.h"
#include "editor/TransportBar.h"
#include "explain/ConservationWidget.h"
#include "explain/EventArrows.h"
#include "explain/ExplainExport.h"
#include "explain/ExplainPanel.h"
#include "explain/ToiChart.h"
#include "lesson/LessonPanel.h"
#include "view/TableView.h"

#include "Explain.h"
#include "SetupFile.h"

#include <QAction>
#include <QDockWidget>
#include <QFile>
#include <QLineEdit>
#include <QMenu>
#include <QPlainTextEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QTabWidget>
#include <QTextBrowser>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace cuelab;

namespace {

const QString kHalfBall = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json");
const QString kExamples = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/");

// |a - b| <= 1e-12 (times the size of b when that is larger than 1), per component.
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12)
{
    return (a - b).cwiseAbs().maxCoeff() <= tol * std::max(1.0, b.cwiseAbs().maxCoeff());
}

QString text(const Vec3& v) { return QStringLiteral("(%1, %2, %3)").arg(v.x(), 0, 'g', 17).arg(v.y(), 0, 'g', 17).arg(v.z(), 0, 'g', 17); }

int firstEvent(const SimulationResult& r, EventKind kind)
{
    for (std::size_t i = 0; i < r.events.size(); ++i)
        if (r.events[i].kind == kind) return int(i);
    return -1;
}

}  // namespace

class TestExplainPanel : public QObject {
    Q_OBJECT
private slots:
    void init()
    {
        window_ = new MainWindow;
        window_->resize(1600, 1000);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_));
        QVERIFY(window_->openFile(kHalfBall));
        window_->document()->waitForResult();
        panel_ = window_->findChild<ExplainPanel*>(QStringLiteral("explainPanel"));
        lesson_ = window_->findChild<LessonPanel*>(QStringLiteral("lessonPanel"));
        QVERIFY(panel_ && lesson_);
    }
    void cleanup()
    {
        window_->document()->undoStack()->setClean();
        delete window_;
        window_ = nullptr;
    }

    void followsSelection()
    {
        const auto r = window_->document()->result();
        const int hit = firstEvent(*r, EventKind::BallBall);
        QVERIFY(hit >= 0);
        window_->selection()->selectEvent(hit);
        QCOMPARE(panel_->shownEvent(), hit);
        QVERIFY(panel_->explanation() && panel_->explanation()->toi);
        QVERIFY(panel_->html().contains(QStringLiteral("Why now")));
        const ToiChart* chart = panel_->findChild<ToiChart*>();
        QVERIFY(chart && chart->markedRoots() >= 1);
        QVERIFY(chart->tauMax() > 0.0);
        // A transition: no polynomial.
        const int roll = firstEvent(*r, EventKind::SlideToRoll);
        window_->selection()->selectEvent(roll);
        QCOMPARE(panel_->shownEvent(), roll);
        QVERIFY(!panel_->explanation()->toi);
        QCOMPARE(chart->markedRoots(), 0);
        // Its chart would be empty: hidden, the derivation gets the room; a collision brings it back.
        QVERIFY(chart->isHidden());
        window_->selection()->selectEvent(hit);
        QVERIFY(!chart->isHidden());
    }

    // ΔE rounded to what matters: an elastic collision's rounding error reads 0 J.
    void energyChangeRounded_data()
    {
        QTest::addColumn<double>("before");
        QTest::addColumn<double>("after");
        QTest::addColumn<QString>("expected");
        QTest::newRow("elastic, rounding") << 0.34 << 0.34 - 1.11e-16 << "ΔE = 0 J (conserved)";
        QTest::newRow("exactly equal") << 0.5 << 0.5 << "ΔE = 0 J (conserved)";
        // 0.45 - 0.5 = -0.05 J of 0.5 J: -10 %.
        QTest::newRow("a tenth lost") << 0.5 << 0.45 << "ΔE = -0.05 J (-10 %)";
        // 1.99 - 2 = -0.01 J of 2 J: -0.5 %.
        QTest::newRow("half a percent") << 2.0 << 1.99 << "ΔE = -0.01 J (-0.5 %)";
        QTest::newRow("from rest") << 0.0 << 0.2 << "ΔE = 0.2 J";
    }

    void energyChangeRounded()
    {
        QFETCH(double, before);
        QFETCH(double, after);
        QFETCH(QString, expected);
        QCOMPARE(ConservationWidget::energyChange(before, after), expected);
    }

    // The figures reflow with the dock: beside each other when wide, the chart above the momenta
    // and energy when narrow (1024-pixel window: a dock of 300 px).
    void figuresReflow()
    {
        // In a scroll area, as in its dock.
        QScrollArea area;
        auto* panel = new ExplainPanel(window_->document(), window_->selection(), window_->playback());
        area.setWidget(panel);
        area.setWidgetResizable(true);
        area.resize(1000, 700);
        area.show();
        QVERIFY(QTest::qWaitForWindowExposed(&area));
        const auto r = window_->document()->result();
        panel->showEvent(firstEvent(*r, EventKind::BallBall));
        QTRY_VERIFY(panel->figuresSideBySide());
        area.resize(300, 900);
        QTRY_VERIFY(!panel->figuresSideBySide());
        auto* conservation = panel->findChild<ConservationWidget*>();
        QVERIFY(conservation);
        QTRY_VERIFY2(conservation->stacked(), qPrintable(QStringLiteral("panel %1 wide, figure %2").arg(panel->width()).arg(conservation->width())));
        QVERIFY(conservation->height() >= 380);
        QVERIFY2(panel->width() <= area.viewport()->width(), "no sideways scrolling");
        // A short dock (Teach at 1280x800: about 350 x 740): the derivation keeps nearly a third of it
        // (before: 80 px of 740, two lines).
        area.resize(350, 740);
        auto* text = panel->findChild<QWidget*>(QStringLiteral("explainText"));
        QVERIFY(text);
        QTRY_VERIFY2(text->height() >= 0.3 * panel->height(),
                     qPrintable(QStringLiteral("text %1 of %2").arg(text->height()).arg(panel->height())));
        QVERIFY(conservation->height() >= 260);
        QCOMPARE(panel->figureLayout(), ExplainPanel::FigureLayout::Stacked);
        // Shorter still (Teach at 1024x700, a dock of about 640 px): both figures would leave the
        // derivation a line or two; one at a time, in tabs, it keeps a third again, and the
        // momenta and energy get their full height (no legend over the bars).
        area.resize(350, 640);
        QTRY_COMPARE(panel->figureLayout(), ExplainPanel::FigureLayout::Tabbed);
        QTRY_VERIFY2(text->height() >= 0.3 * panel->height(),
                     qPrintable(QStringLiteral("text %1 of %2").arg(text->height()).arg(panel->height())));
        auto* tabs = panel->findChild<QTabWidget*>(QStringLiteral("explainFigureTabs"));
        QVERIFY(tabs);
        QCOMPARE(tabs->count(), 2);
        tabs->setCurrentIndex(1);
        QTRY_VERIFY(conservation->isVisible());
        QVERIFY(conservation->height() >= 380);
        // The cue strike's time is closed-form: no chart, so no tab for it, and the other is shown.
        const auto strike = firstEvent(*r, EventKind::CueStrike);
        QVERIFY(strike >= 0);
        panel->showEvent(strike);
        QCOMPARE(tabs->isTabVisible(0), false);
        QCOMPARE(tabs->isTabVisible(1), true);
        QTRY_VERIFY(conservation->isVisible());
        panel->showEvent(firstEvent(*r, EventKind::BallBall));
        QCOMPARE(tabs->isTabVisible(0), true);
        // Taller again, both figures come back, stacked.
        area.resize(350, 900);
        QTRY_COMPARE(panel->figureLayout(), ExplainPanel::FigureLayout::Stacked);
        QCOMPARE(tabs->count(), 0);
        QTRY_VERIFY(conservation->isVisible());
    }

    // Page Down scrolls a focused derivation (it is the transport's next event elsewhere); another
    // event opens at its heading.
    void pageKeysScrollTheDerivation()
    {
        window_->resize(1024, 700);
        const auto r = window_->document()->result();
        const int hit = firstEvent(*r, EventKind::BallBall);
        QVERIFY(hit >= 0);
        window_->selection()->selectEvent(hit);
        auto* text = panel_->findChild<QTextBrowser*>(QStringLiteral("explainText"));
        QVERIFY(text && text->isVisible());
        QScrollBar* bar = text->verticalScrollBar();
        QTRY_VERIFY2(bar->maximum() > 0, "the derivation should need scrolling at 1024x700");
        window_->activateWindow();
        text->setFocus();
        QTRY_VERIFY(text->hasFocus());
        const double t = window_->playback()->time();
        QCOMPARE(bar->value(), 0);
        QTest::keyClick(text, Qt::Key_PageDown);
        QVERIFY2(bar->value() > 0, "Page Down did not scroll the derivation");
        QCOMPARE(panel_->shownEvent(), hit);
        QCOMPARE(window_->playback()->time(), t);
        QTest::keyClick(text, Qt::Key_End);
        QCOMPARE(bar->value(), bar->maximum());
        QTest::keyClick(text, Qt::Key_PageUp);
        QVERIFY(bar->value() < bar->maximum());
        QTest::keyClick(text, Qt::Key_Home);
        QCOMPARE(bar->value(), 0);
        QTest::keyClick(text, Qt::Key_End);
        // Another event: at its heading.
        const int roll = firstEvent(*r, EventKind::SlideToRoll);
        window_->selection()->selectEvent(roll);
        QCOMPARE(panel_->shownEvent(), roll);
        QCOMPARE(bar->value(), 0);
        // Elsewhere Page Down is still the next event.
        window_->tableView()->setFocus();
        QTRY_VERIFY(window_->tableView()->hasFocus());
        window_->playback()->toStart();
        QTest::keyClick(window_->tableView(), Qt::Key_PageDown);
        QVERIFY(window_->playback()->time() > 0.0);
    }

    void followsTransport()
    {
        const auto r = window_->document()->result();
        window_->playback()->toStart();
        window_->playback()->nextEvent();
        const double t = window_->playback()->time();
        QVERIFY(panel_->shownEvent() >= 0);
        QCOMPARE(r->events[std::size_t(panel_->shownEvent())].time, t);
        window_->playback()->nextEvent();
        QVERIFY(window_->playback()->time() > t);
        QCOMPARE(r->events[std::size_t(panel_->shownEvent())].time, window_->playback()->time());
    }

    void lessonShownAndUndoable()
    {
        const Setup& s = window_->document()->setup();
        QVERIFY(!s.name.empty());
        QCOMPARE(lesson_->nameEdit()->text(), QString::fromStdString(s.name));
        QCOMPARE(lesson_->notesEdit()->toPlainText(), QString::fromStdString(s.notes));
        const std::string before = s.name;
        QUndoStack* undo = window_->document()->undoStack();
        const int steps = undo->count();
        lesson_->nameEdit()->setText(QStringLiteral("My cut"));
        lesson_->commit();
        QCOMPARE(window_->document()->setup().name, std::string("My cut"));
        QCOMPARE(undo->count(), steps + 1);
        lesson_->notesEdit()->setPlainText(QStringLiteral("Aim at the half-ball point."));
        lesson_->commit();
        QCOMPARE(window_->document()->setup().notes, std::string("Aim at the half-ball point."));
        QCOMPARE(undo->count(), steps + 2);
        lesson_->commit();  // nothing changed: no step
        QCOMPARE(undo->count(), steps + 2);
        undo->undo();
        undo->undo();
        QCOMPARE(window_->document()->setup().name, before);
        QCOMPARE(lesson_->nameEdit()->text(), QString::fromStdString(before));
        undo->redo();
        QCOMPARE(lesson_->nameEdit()->text(), QStringLiteral("My cut"));
    }

    void exportAction()
    {
        QAction* action = window_->findChild<QAction*>(QStringLiteral("exportExplanationAction"));
        QVERIFY(action);
        const auto r = window_->document()->result();
        QTemporaryDir dir;
        QString error;
        const std::vector<int> all = collisionEvents(*r);
        QVERIFY(!all.empty());
        QVERIFY(exportExplanations(dir.filePath("shot.html"), *r, window_->document()->setup().shot, all, "Half-ball cut", &error));
        QVERIFY(exportExplanations(dir.filePath("shot.md"), *r, window_->document()->setup().shot, all, "Half-ball cut", &error));
        QFile html(dir.filePath("shot.html")), md(dir.filePath("shot.md"));
        QVERIFY(html.open(QIODevice::ReadOnly) && md.open(QIODevice::ReadOnly));
        const QByteArray h = html.readAll(), m = md.readAll();
        QVERIFY(h.startsWith("<!DOCTYPE html>") && h.contains("<sub>"));
        QVERIFY(m.startsWith("# Half-ball cut") && m.count("Why now") == int(all.size()));
        // A folder that does not exist: refused with a message, nothing half-written.
        QVERIFY(!exportExplanations(dir.filePath("no/such/dir/x.md"), *r, {}, all, "x", &error));
        QVERIFY(!error.isEmpty());
    }

    void screenshot()
    {
        const auto r = window_->document()->result();
        window_->selection()->selectEvent(firstEvent(*r, EventKind::BallBall));
        // The dock is an ancestor (every dock's content sits in a scroll area).
        QDockWidget* dock = nullptr;
        for (QWidget* w = panel_->parentWidget(); w && !dock; w = w->parentWidget()) dock = qobject_cast<QDockWidget*>(w);
        QVERIFY(dock);
        dock->show();
        dock->raise();
        dock->setFloating(true);
        dock->resize(820, 1100);
        QTest::qWait(200);
        const QImage image = panel_->grab().toImage();
        QVERIFY(image.width() > 400 && image.height() > 600);
        QVERIFY(image.save(QStringLiteral(CUELAB_BINARY_DIR "/explain-dock.png")));
    }

    // The layer of every collision of several shots against the simulator's own event: the marker
    // and the normal and impulse arrows start at the contact point, the momentum arrows at the
    // balls' centres, and each points along the event's vector at the stated scale.
    void arrowsComeFromTheEvent_data()
    {
        QTest::addColumn<QString>("example");
        for (const char* name : {"half-ball-cut.json", "one-cushion-bank.json", "two-rail-kick.json", "9-ball-break.json"})
            QTest::newRow(name) << QString::fromLatin1(name);
    }
    void arrowsComeFromTheEvent()
    {
        QFETCH(QString, example);
        QString error;
        const std::optional<Setup> setup = io::loadSetup(kExamples + example, &error);
        QVERIFY2(setup, qPrintable(error));
        const SimulationResult r = simulate(*setup);
        int collisions = 0, others = 0, vertical = 0;
        for (int i = 0; i < int(r.events.size()); ++i) {
            const Event& ev = r.events[std::size_t(i)];
            const explain::Explanation e = explain::explain(r, i, setup->shot);
            const ViewLayer layer = eventArrowsLayer(e);
            if (!isCollision(ev.kind)) {
                QVERIFY2(layer.empty(), qPrintable(QStringLiteral("event %1 is no collision").arg(i)));
                ++others;
                continue;
            }
            ++collisions;
            const int bodies = ev.kind == EventKind::BallBall ? 2 : 1;
            double top = 0.0;
            for (int k = 0; k < bodies; ++k) top = std::max(top, 2.0 * r.balls[std::size_t(ev.balls[std::size_t(k)])].radius);
            const double z = top + kArrowPlaneLift;
            QCOMPARE(arrowPlaneHeight(e), z);
            const Vec3 contact(ev.contactPoint.x(), ev.contactPoint.y(), z);
            QCOMPARE(layer.markers.size(), std::size_t(1));
            QVERIFY(near(layer.markers[0].position, contact));
            // The marker says what it marks; the scale is the layer's legend, apart from every label.
            QCOMPARE(layer.markers[0].label, QStringLiteral("contact"));
            QVERIFY(layer.legend.contains(QStringLiteral("1 N·s = 1 m")));
            for (const LayerArrow& a : layer.arrows) QVERIFY2(!a.label.contains(QStringLiteral(" = 1 m")), qPrintable(a.label));
            QVERIFY(layer.arrows.size() >= 3);
            const LayerArrow& n = layer.arrows.back();
            QCOMPARE(n.label, QStringLiteral("n"));
            QVERIFY(near(n.from, contact));
            QVERIFY2(near((n.to - n.from) / kNormalArrowLength, Vec3(ev.normal.x(), ev.normal.y(), 0.0)), qPrintable(text(n.to)));
            const LayerArrow& j = layer.arrows[layer.arrows.size() - 2];
            QVERIFY(near(j.from, contact));
            // Its horizontal part; the vertical part (a cushion nose above the centre) in the label.
            const Vec3 horizontal(ev.impulse.x(), ev.impulse.y(), 0.0);
            QVERIFY2(near((j.to - j.from) / kArrowMetresPerNewtonSecond, horizontal), qPrintable(text(j.to - j.from)));
            const QString magnitude = QString::number(horizontal.norm(), 'f', 3);
            QCOMPARE(j.label, std::abs(ev.impulse.z()) < 5e-4
                                  ? QStringLiteral("J = %1 N·s").arg(magnitude)
                                  : QStringLiteral("J = %1 N·s, vertical %2 N·s").arg(magnitude, QString::number(ev.impulse.z(), 'f', 3)));
            if (std::abs(ev.impulse.z()) >= 5e-4) ++vertical;
            // The momenta: one arrow per ball and phase in which the ball moves, from its centre.
            std::size_t next = 0;
            for (int k = 0; k < bodies; ++k) {
                const Ball& ball = r.balls[std::size_t(ev.balls[std::size_t(k)])];
                const Vec3 centre(ev.before[std::size_t(k)].position.x(), ev.before[std::size_t(k)].position.y(), z);
                for (const BallState* s : {&ev.before[std::size_t(k)], &ev.after[std::size_t(k)]}) {
                    const Vec2 p = ball.mass * s->velocity;
                    if (kArrowMetresPerNewtonSecond * p.norm() < 1e-4) continue;
                    QVERIFY(next < layer.arrows.size());
                    const LayerArrow& a = layer.arrows[next++];
                    QVERIFY(near(a.from, centre));
                    QVERIFY2(near((a.to - a.from) / kArrowMetresPerNewtonSecond, Vec3(p.x(), p.y(), 0.0)), qPrintable(text(a.to)));
                    QVERIFY2(a.label.startsWith((s == &ev.before[std::size_t(k)] ? QStringLiteral("p ") : QStringLiteral("p′ ")) +
                                                QString::fromStdString(ball.id) + QStringLiteral(" = ")),
                             qPrintable(a.label));
                    QVERIFY(a.label.endsWith(QStringLiteral("%1 N·s").arg(p.norm(), 0, 'f', 3)));
                }
            }
            QCOMPARE(layer.arrows.size(), next + 2);
            // Every momentum arrow has its own colour (each ball its p and p′), none the impulse's.
            for (std::size_t a = 0; a < next; ++a) {
                QVERIFY(layer.arrows[a].colour != layer.arrows[next].colour);
                for (std::size_t b = a + 1; b < next; ++b)
                    QVERIFY2(layer.arrows[a].colour != layer.arrows[b].colour,
                             qPrintable(layer.arrows[a].label + QStringLiteral(" / ") + layer.arrows[b].label));
            }
            // The impulse is the first ball's change of momentum: on screen, p′ = p + J.
            const Ball& first = r.balls[std::size_t(ev.balls[0])];
            const Vec2 change = first.mass * (ev.after[0].velocity - ev.before[0].velocity);
            QVERIFY2((change - ev.impulse.head<2>()).norm() <= 1e-9, qPrintable(QString::number((change - ev.impulse.head<2>()).norm())));
        }
        QVERIFY(collisions >= 1);
        QVERIFY(others >= 1);
        if (example == QLatin1String("two-rail-kick.json")) QVERIFY(vertical >= 1);  // Han 2005 cushions
    }

    // Selecting a collision puts its layer in the view (and the transport's next-event step does
    // too); a transition, a ball or no event clears it; View > Overlays > Collision Arrows hides it.
    void arrowsFollowTheSelection()
    {
        TableView* view = window_->tableView();
        QAction* toggle = window_->findChild<QAction*>(QStringLiteral("collisionArrowsAction"));
        QVERIFY(toggle && toggle->isCheckable() && !toggle->toolTip().isEmpty());
        const auto* overlays = window_->findChild<QMenu*>(QStringLiteral("overlaysMenu"));
        QVERIFY(overlays && overlays->actions().contains(toggle));
        toggle->setChecked(true);
        const auto r = window_->document()->result();
        const int hit = firstEvent(*r, EventKind::BallBall);
        const int roll = firstEvent(*r, EventKind::SlideToRoll);
        QVERIFY(hit >= 0 && roll >= 0);
        auto layer = [view]() -> const ViewLayer* {
            const auto it = view->layers().find(kEventArrowsLayer);
            return it == view->layers().end() ? nullptr : &it->second;
        };
        QVERIFY(!layer());
        window_->selection()->selectEvent(hit);
        QVERIFY(layer());
        QVERIFY(layer()->visible);
        const ViewLayer expected = eventArrowsLayer(explain::explain(*r, hit, window_->document()->setup().shot));
        QCOMPARE(layer()->arrows.size(), expected.arrows.size());
        for (std::size_t k = 0; k < expected.arrows.size(); ++k) {
            QVERIFY(near(layer()->arrows[k].from, expected.arrows[k].from, 0.0));
            QVERIFY(near(layer()->arrows[k].to, expected.arrows[k].to, 0.0));
            QCOMPARE(layer()->arrows[k].label, expected.arrows[k].label);
        }
        window_->selection()->selectEvent(roll);  // a transition: nothing to draw
        QVERIFY(!layer());
        window_->selection()->selectEvent(hit);
        QVERIFY(layer());
        window_->selection()->selectBall(0);  // the event is no longer selected
        QVERIFY(!layer());
        window_->selection()->selectEvent(hit);
        window_->selection()->selectEvent(-1);
        QVERIFY(!layer());

        // The transport's step lands on the collision and selects it.
        window_->playback()->toStart();
        QAction* next = window_->transportBar()->nextEventAction();
        for (int k = 0; k < int(r->events.size()) && window_->selection()->event() != hit; ++k) next->trigger();
        QCOMPARE(window_->selection()->event(), hit);
        QVERIFY(layer());
        next->trigger();
        QVERIFY(window_->selection()->event() != hit);
        QCOMPARE(layer() != nullptr, isCollision(r->events[std::size_t(window_->selection()->event())].kind));

        // The toggle hides the arrows and shows them again; a collision selected while hidden stays hidden.
        window_->selection()->selectEvent(hit);
        toggle->setChecked(false);
        QVERIFY(layer() && !layer()->visible);
        window_->selection()->selectEvent(roll);
        window_->selection()->selectEvent(hit);
        QVERIFY(layer() && !layer()->visible);
        toggle->setChecked(true);
        QVERIFY(layer() && layer()->visible);
        // A new document: nothing selected, no arrows.
        QVERIFY(window_->openFile(kHalfBall));
        window_->document()->waitForResult();
        QVERIFY(!layer());
    }

private:
    MainWindow* window_ = nullptr;
    ExplainPanel* panel_ = nullptr;
    LessonPanel* lesson_ = nullptr;
};

QTEST_MAIN(TestExplainPanel)
#include "tst_explainpanel.moc"
