// Predictions without spoilers (issue 44, item 3): while a question of predict-then-reveal waits,
// nothing in the window shows what happens after its moment (the Events list, the status line, the
// outcome line and dock, the plots, the time slider and its ticks, Explain, the Predict dock's own
// question list); after the reveal everything shows again. The half-ball cut pockets the 1 ball
// after the first collision, so the pocketing is the spoiler looked for.

#include "MainWindow.h"
#include "analysis/AnalysisPanel.h"
#include "compare/ComparePanel.h"
#include "editor/Document.h"
#include "editor/EventTreeModel.h"
#include "editor/EventsPanel.h"
#include "editor/Playback.h"
#include "editor/RunState.h"
#include "editor/Selection.h"
#include "editor/TimelineSlider.h"
#include "editor/TransportBar.h"
#include "explain/ExplainPanel.h"
#include "lesson/PredictPanel.h"
#include "lesson/PredictSession.h"
#include "lesson/SpoilerCurtain.h"
#include "outcome/OutcomePanel.h"
#include "plots/PlotsPanel.h"
#include "view/TableView.h"

#include "Horizon.h"
#include "Prediction.h"

#include <QDockWidget>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <algorithm>
#include <numbers>

using namespace cuelab;

namespace {

const QString kHalfBall = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json");

// A left-button drag in the view through `path`.
void drag(TableView* view, const QList<QPointF>& path)
{
    const auto send = [view](QEvent::Type type, const QPointF& pos, Qt::MouseButton button, Qt::MouseButtons buttons) {
        QMouseEvent e(type, pos, view->mapToGlobal(pos), button, buttons, Qt::NoModifier);
        QCoreApplication::sendEvent(view, &e);
    };
    send(QEvent::MouseButtonPress, path.front(), Qt::LeftButton, Qt::LeftButton);
    for (qsizetype i = 1; i < path.size(); ++i) send(QEvent::MouseMove, path[i], Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, path.back(), Qt::LeftButton, Qt::NoButton);
}

// Where a table point (m, at a ball's centre height) shows in the view.
QPointF at(const TableView& view, double x, double y)
{
    constexpr float kR = 0.028575f;  // m, a pool ball's radius
    return view.widgetPointOf(QVector3D(float(x), float(y), kR)).value_or(QPointF(-1.0, -1.0));
}

// Every text of a model's rows (and their children), all columns.
QStringList allTexts(const QAbstractItemModel& model, const QModelIndex& parent = {})
{
    QStringList texts;
    for (int row = 0; row < model.rowCount(parent); ++row)
        for (int column = 0; column < model.columnCount(parent); ++column) {
            const QModelIndex index = model.index(row, column, parent);
            texts << model.data(index, Qt::DisplayRole).toString();
            if (column == 0) texts << allTexts(model, index);
        }
    return texts;
}

// The latest time any plotted line reaches (s).
double lastPlottedTime(const PlotsPanel& plots)
{
    double last = 0.0;
    for (const PlotsPanel::Line& line : plots.lines())
        for (const plots::Polyline& piece : line.curve)
            if (!piece.times.empty()) last = std::max(last, piece.times.back());
    return last;
}

}  // namespace

class TestPredictSpoilers : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings_.path());
    }
    void init()
    {
        QSettings().clear();
        QSettings().setValue(QStringLiteral("help/firstStartTipSeen"), true);
        window_ = new MainWindow;
        window_->resize(1600, 1000);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_));
        QVERIFY(window_->openFile(kHalfBall));
        window_->document()->waitForResult();
        panel_ = window_->findChild<PredictPanel*>(QStringLiteral("predictPanel"));
        QVERIFY(panel_);
        whole_ = window_->document()->result();
        QVERIFY(whole_);
        hit_ = lesson::firstCollisionEvent(*whole_);
        QVERIFY(hit_ > 0);
        tHit_ = whole_->events[std::size_t(hit_)].time;
        // The spoiler: the 1 ball's pocketing, after the collision asked about.
        pocketing_ = -1;
        for (std::size_t i = 0; i < whole_->events.size(); ++i)
            if (whole_->events[i].kind == EventKind::BallPocket) pocketing_ = int(i);
        QVERIFY(pocketing_ > hit_);
    }
    void cleanup()
    {
        window_->document()->undoStack()->setClean();
        delete window_;
        window_ = nullptr;
    }

    void theCutRunIsTheRunUpToTheQuestion();
    void beforeTheRevealNothingShowsWhatFollows();
    void theRevealShowsEverything();
    void aLaterQuestionStaysHiddenAfterTheFirstReveal();
    void stopShowsEverything();
    void aimingKeysAreLockedWhileAQuestionWaits();
    void aimDragsAreLockedUntilTheLastReveal();
    void compareAndAnalysisWaitForTheReveal();

private:
    void startAndWaitForQuestion();
    // Every panel shows the shot up to `horizon` (s) only: asserted panel by panel.
    void verifyShownUpTo(double horizon);
    void verifyWholeShown();

    QLabel* statusLabel(const char* name) const { return window_->findChild<QLabel*>(QLatin1String(name)); }

    QTemporaryDir settings_;
    MainWindow* window_ = nullptr;
    PredictPanel* panel_ = nullptr;
    std::shared_ptr<const SimulationResult> whole_;
    int hit_ = -1;
    double tHit_ = 0.0;
    int pocketing_ = -1;
};

void TestPredictSpoilers::startAndWaitForQuestion()
{
    window_->playback()->setSpeed(4.0);
    QTest::mouseClick(panel_->startButton(), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(panel_->session()->state(), PredictSession::State::Asking, 20000);
}

void TestPredictSpoilers::theCutRunIsTheRunUpToTheQuestion()
{
    // core/lesson's cut equals the simulator's own run stopped at the question's time (Horizon.h).
    const SimulationResult shown = lesson::shownBefore(*whole_, tHit_);
    QCOMPARE(shown.events.size(), std::size_t(hit_));
    QCOMPARE(shown.endTime, tHit_);
    QVERIFY(shown.status == SimulationStatus::ReachedUntil);
    for (int b = 0; b < int(whole_->balls.size()); ++b) {
        const double t = tHit_ - PredictSession::kStopBefore;
        QVERIFY(shown.stateAt(b, t).position == whole_->stateAt(b, t).position);
    }
    // A horizon beyond the end is the whole run.
    QCOMPARE(lesson::shownBefore(*whole_, whole_->endTime + 1.0).events.size(), whole_->events.size());
}

void TestPredictSpoilers::verifyShownUpTo(double horizon)
{
    int before = 0;
    for (const Event& e : whole_->events)
        if (e.time < horizon) ++before;
    QVERIFY(before < int(whole_->events.size()));

    // Events: only the events before the question, nothing of the pocketing.
    EventTreeModel* model = window_->eventsPanel()->model();
    QCOMPARE(model->listedEventCount(), before);
    for (int row = 0; row < model->rowCount(); ++row) {
        const int event = model->eventAt(model->index(row, 0));
        QVERIFY2(event >= 0 && whole_->events[std::size_t(event)].time < horizon, qPrintable(QString::number(event)));
    }
    const QString events = allTexts(*model).join(QLatin1Char('|'));
    QVERIFY2(!events.contains(QStringLiteral("pocket")), qPrintable(events));

    // The status line and the outcome: the shot so far, said to be so; no pocket named.
    const QString summary = statusLabel("summaryStatus")->text();
    QVERIFY2(summary.startsWith(QStringLiteral("%1 event").arg(before)) && summary.contains(QStringLiteral("before the question")),
             qPrintable(summary));
    QVERIFY2(!summary.contains(QStringLiteral("at rest")), qPrintable(summary));
    const QString outcome = statusLabel("outcomeStatus")->text();
    QVERIFY2(outcome.contains(RunState::withheldNote(horizon)), qPrintable(outcome));
    QVERIFY2(!outcome.contains(QStringLiteral("top-right pocket")) && !outcome.contains(QStringLiteral("(pocket")), qPrintable(outcome));
    auto* outcomePanel = window_->findChild<OutcomePanel*>();
    QVERIFY(outcomePanel);
    QVERIFY(outcomePanel->outcome().pocketed.empty());
    QVERIFY(!outcomePanel->verdict());
    QCOMPARE(outcomePanel->factsTable()->rowCount(), 0);
    QCOMPARE(outcomePanel->ballsTable()->rowCount(), 0);
    QCOMPARE(window_->findChild<QLabel*>(QStringLiteral("outcomeSummary"))->text(), outcome);

    // Plots: the curves end at the horizon.
    auto* plots = window_->findChild<PlotsPanel*>();
    QVERIFY(plots);
    QVERIFY(!plots->lines().empty());
    QVERIFY2(lastPlottedTime(*plots) <= horizon + 1e-12, qPrintable(QString::number(lastPlottedTime(*plots), 'g', 17)));

    // The time slider: it ends at the horizon, and its ticks are the shown events'.
    QCOMPARE(window_->playback()->endTime(), horizon);
    QCOMPARE(window_->playback()->eventTimes().size(), std::size_t(before));
    TimelineSlider* slider = window_->transportBar()->slider();
    QCOMPARE(slider->ticks().size(), std::size_t(before));
    for (const int tick : slider->ticks()) QVERIFY(slider->timeAt(tick) <= horizon);
    QVERIFY(slider->timeAt(slider->maximum()) <= horizon + TimelineSlider::kSecondsPerStep);
    // Dragging the time to the end stops at the question.
    const double asked = window_->playback()->time();
    window_->playback()->setTime(whole_->endTime);
    QCOMPARE(window_->playback()->time(), horizon);
    window_->playback()->setTime(asked);

    // Explain: a later event cannot be chosen, and none is explained.
    window_->selection()->selectEvent(pocketing_);
    QCOMPARE(window_->selection()->event(), -1);
    auto* explain = window_->findChild<ExplainPanel*>();
    QVERIFY(explain);
    QVERIFY(explain->shownEvent() < before);

    // The view's scene: the run up to the horizon.
    QCOMPARE(window_->tableView()->scene().result->endTime, horizon);

    // The Predict dock's own list of questions does not name a later event either.
    for (int row = 0; row < panel_->questionsTable()->rowCount(); ++row) {
        const QString stops = panel_->questionsTable()->item(row, 0)->text();
        QVERIFY2(!stops.contains(QStringLiteral("ball-pocket")), qPrintable(stops));
    }

    // All through one mechanism: the document hands every panel the run up to the horizon.
    Document* d = window_->document();
    QVERIFY(d->isWithholding());
    QCOMPARE(d->result()->events.size(), std::size_t(before));
    QCOMPARE(d->wholeResult(), whole_);
}

void TestPredictSpoilers::verifyWholeShown()
{
    Document* d = window_->document();
    QVERIFY(!d->isWithholding());
    QCOMPARE(d->result(), whole_);
    EventTreeModel* model = window_->eventsPanel()->model();
    QCOMPARE(model->listedEventCount(), int(whole_->events.size()));
    QVERIFY(allTexts(*model).join(QLatin1Char('|')).contains(QStringLiteral("ball-pocket")));
    QVERIFY(statusLabel("summaryStatus")->text().contains(QStringLiteral("at rest")));
    const QString outcome = statusLabel("outcomeStatus")->text();
    QVERIFY2(outcome.contains(QStringLiteral("top-right pocket")), qPrintable(outcome));
    QVERIFY(!outcome.contains(QStringLiteral("Until the reveal")));
    auto* plots = window_->findChild<PlotsPanel*>();
    QVERIFY(lastPlottedTime(*plots) > whole_->events[std::size_t(pocketing_)].time);
    QCOMPARE(window_->playback()->endTime(), whole_->endTime);
    QCOMPARE(window_->transportBar()->slider()->ticks().size(), whole_->events.size());
    window_->selection()->selectEvent(pocketing_);
    QCOMPARE(window_->selection()->event(), pocketing_);
    QCOMPARE(window_->findChild<ExplainPanel*>()->shownEvent(), pocketing_);
    window_->selection()->selectEvent(-1);
}

void TestPredictSpoilers::beforeTheRevealNothingShowsWhatFollows()
{
    // Before the mode starts, the window does show the pocketing (what the checks below look for).
    verifyWholeShown();
    startAndWaitForQuestion();
    verifyShownUpTo(tHit_);
}

void TestPredictSpoilers::theRevealShowsEverything()
{
    startAndWaitForQuestion();
    verifyShownUpTo(tHit_);
    QTest::mouseClick(panel_->revealButton(), Qt::LeftButton);
    QCOMPARE(panel_->session()->state(), PredictSession::State::Revealed);
    // It plays on from the question (verifyWholeShown selects an event: that pauses).
    QVERIFY(window_->playback()->isPlaying());
    verifyWholeShown();
    window_->playback()->play();
    QTRY_COMPARE_WITH_TIMEOUT(panel_->session()->state(), PredictSession::State::Finished, 30000);
    verifyWholeShown();
}

void TestPredictSpoilers::aLaterQuestionStaysHiddenAfterTheFirstReveal()
{
    // Two questions: the first collision, then the pocketing. Revealing the first shows the shot up to
    // the second only.
    Setup s = window_->document()->setup();
    PredictQuestion first;
    first.event = hit_;
    PredictQuestion second;
    second.event = pocketing_;
    s.questions = {first, second};
    QVERIFY(window_->document()->edit(QStringLiteral("Two questions"), s));
    window_->document()->waitForResult();
    whole_ = window_->document()->result();
    const double tPocket = whole_->events[std::size_t(pocketing_)].time;
    startAndWaitForQuestion();
    verifyShownUpTo(tHit_);
    // The second question's row names only its event's number before its reveal.
    const QString secondStops = panel_->questionsTable()->item(1, 0)->text();
    QVERIFY2(secondStops.startsWith(QStringLiteral("#%1 ").arg(pocketing_ + 1)), qPrintable(secondStops));
    QTest::mouseClick(panel_->revealButton(), Qt::LeftButton);
    QVERIFY(window_->document()->isWithholding());
    QCOMPARE(*window_->document()->horizon(), tPocket);
    QCOMPARE(window_->playback()->endTime(), tPocket);
    QTRY_COMPARE_WITH_TIMEOUT(panel_->session()->current(), 1, 30000);
    QTRY_COMPARE_WITH_TIMEOUT(panel_->session()->state(), PredictSession::State::Asking, 30000);
    verifyShownUpTo(tPocket);
    QTest::mouseClick(panel_->revealButton(), Qt::LeftButton);
    verifyWholeShown();
}

void TestPredictSpoilers::stopShowsEverything()
{
    startAndWaitForQuestion();
    verifyShownUpTo(tHit_);
    QTest::mouseClick(panel_->startButton(), Qt::LeftButton);  // Stop
    QCOMPARE(panel_->session()->state(), PredictSession::State::Idle);
    verifyWholeShown();
}

void TestPredictSpoilers::aimingKeysAreLockedWhileAQuestionWaits()
{
    // Ctrl+Left turns the cue at any time; during a question it would edit the shot, end the session
    // and show the (almost) same shot whole: the answer. Locked, it changes nothing and says why.
    startAndWaitForQuestion();
    TableView* view = window_->tableView();
    Document* d = window_->document();
    const CueStrike shot = *d->setup().shot;
    const int steps = d->undoStack()->count();
    view->setFocus();
    QTest::keyClick(view, Qt::Key_Left, Qt::ControlModifier);
    QTest::keyClick(view, Qt::Key_Up, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(d->setup().shot->headingDeg, shot.headingDeg);
    QCOMPARE(d->setup().shot->speed, shot.speed);
    QCOMPARE(d->undoStack()->count(), steps);
    QCOMPARE(panel_->session()->state(), PredictSession::State::Asking);
    QCOMPARE(window_->statusBar()->currentMessage(), PredictSession::lockedWhy());
    verifyShownUpTo(tHit_);

    // After the (only) reveal the keys aim again.
    QTest::mouseClick(panel_->revealButton(), Qt::LeftButton);
    QVERIFY(view->editLock().isEmpty());
    window_->playback()->pause();
    view->setFocus();
    QTest::keyClick(view, Qt::Key_Left, Qt::ControlModifier);
    QCOMPARE(d->setup().shot->headingDeg, shot.headingDeg + 0.1);
}

void TestPredictSpoilers::aimDragsAreLockedUntilTheLastReveal()
{
    // Two questions: after the first reveal the second still waits. Back at t = 0 the cue can be
    // dragged, a ball too; locked, neither moves, and the second question stays hidden.
    Setup s = window_->document()->setup();
    PredictQuestion first;
    first.event = hit_;
    PredictQuestion second;
    second.event = pocketing_;
    s.questions = {first, second};
    QVERIFY(window_->document()->edit(QStringLiteral("Two questions"), s));
    window_->document()->waitForResult();
    whole_ = window_->document()->result();
    startAndWaitForQuestion();
    QTest::mouseClick(panel_->revealButton(), Qt::LeftButton);
    window_->playback()->pause();
    window_->playback()->setTime(0.0);
    QCOMPARE(panel_->session()->state(), PredictSession::State::Revealed);
    TableView* view = window_->tableView();
    view->setCameraPreset(CameraPreset::Top, false);
    QCoreApplication::processEvents();
    Document* d = window_->document();
    const CueStrike shot = *d->setup().shot;
    const Vec2 cue = d->setup().balls[0].state.position;
    QVERIFY(d->setup().balls[0].id == shot.ball);
    const double h = shot.headingDeg * std::numbers::pi / 180.0;
    const Vec2 back(-std::cos(h), -std::sin(h));
    // The cue, 0.4 m behind the ball: something to aim with (the lock does not hide it).
    const Vec2 grab = cue + 0.4 * back;
    QCOMPARE(view->aim().handleAt(at(*view, grab.x(), grab.y())), AimHandle::Cue);
    QList<QPointF> swing;
    for (int k = 0; k <= 10; ++k) swing << at(*view, grab.x() + 0.01 * k * back.y(), grab.y() - 0.01 * k * back.x());
    window_->statusBar()->clearMessage();
    drag(view, swing);
    QCOMPARE(d->setup().shot->headingDeg, shot.headingDeg);
    QCOMPARE(window_->statusBar()->currentMessage(), PredictSession::lockedWhy());
    // The cue ball dragged 10 cm sideways stays where it is.
    QList<QPointF> move;
    for (int k = 0; k <= 10; ++k) move << at(*view, cue.x(), cue.y() - 0.01 * k);
    drag(view, move);
    QVERIFY(d->setup().balls[0].state.position == cue);
    QCOMPARE(panel_->session()->state(), PredictSession::State::Revealed);
    QVERIFY(d->isWithholding());
    QCOMPARE(*d->horizon(), whole_->events[std::size_t(pocketing_)].time);
}

void TestPredictSpoilers::compareAndAnalysisWaitForTheReveal()
{
    // Both docks run the shot themselves: before the reveal each shows only the curtain's line.
    auto* compareDock = window_->findChild<QDockWidget*>(QStringLiteral("CompareDock"));
    auto* analysisDock = window_->findChild<QDockWidget*>(QStringLiteral("AnalysisDock"));
    QVERIFY(compareDock && analysisDock);
    compareDock->show();
    analysisDock->show();
    analysisDock->raise();
    auto* compare = window_->findChild<ComparePanel*>();
    auto* analysis = window_->findChild<AnalysisPanel*>();
    QVERIFY(compare && analysis);
    compare->waitForIdle();
    QTRY_VERIFY(compare->comparison() != nullptr);
    QCoreApplication::processEvents();
    QVERIFY(compare->isVisible() && analysis->isVisible());
    QVERIFY(window_->tableView()->layers().count(QStringLiteral("compare")) == 1);

    startAndWaitForQuestion();
    QVERIFY(!compare->isVisible());
    QVERIFY(!analysis->isVisible());
    const QList<SpoilerCurtain*> curtains = window_->findChildren<SpoilerCurtain*>();
    QCOMPARE(curtains.size(), 2);
    for (SpoilerCurtain* curtain : curtains) {
        QVERIFY(curtain->isDrawn());
        QVERIFY(curtain->noteLabel()->isVisible());
        QCOMPARE(curtain->noteLabel()->text(), SpoilerCurtain::note());
    }
    // Nor do the other engine's ghost balls stay in the view.
    QCOMPARE(window_->tableView()->layers().count(QStringLiteral("compare")), std::size_t(0));

    QTest::mouseClick(panel_->revealButton(), Qt::LeftButton);
    QVERIFY(compare->isVisible() && analysis->isVisible());
    for (SpoilerCurtain* curtain : curtains) QVERIFY(!curtain->isDrawn());
    QCOMPARE(window_->tableView()->layers().count(QStringLiteral("compare")), std::size_t(1));
}

QTEST_MAIN(TestPredictSpoilers)
#include "tst_predictspoilers.moc"
