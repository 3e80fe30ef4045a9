// Issue 39: the window never shows a stale result and never jams. A slow shot (seconds of CPU,
// tests/core/fixtures/slow) is opened and then replaced, edited, cancelled, or the window is quit while it runs.

#include "MainWindow.h"

#include "editor/Document.h"
#include "editor/EventsPanel.h"
#include "editor/SimulationOverlay.h"
#include "view/TableView.h"

#include "SetupFile.h"
#include "ExamplePath.h"

#include <QAction>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>
#include <QThreadPool>
#include <QtTest>

#include <memory>

using namespace cuelab;

namespace {

// A shot that costs the simulator seconds (tests/core/fixtures/slow).
QString slowShot() { return QStringLiteral(CUELAB_SOURCE_DIR "/tests/core/fixtures/slow/cluster-144-balls-struck.json"); }

std::vector<Event> eventsOf(const QString& path)
{
    QString error;
    const std::optional<Setup> s = io::loadSetup(path, &error);
    if (!s) qFatal("%s", qPrintable(error));
    return simulate(*s).events;
}

QAction* menuAction(QMenuBar* bar, const QString& menu, const QString& item)
{
    for (QAction* m : bar->actions()) {
        if (m->text().remove(QLatin1Char('&')) != menu || !m->menu()) continue;
        for (QAction* a : m->menu()->actions())
            if (a->text().remove(QLatin1Char('&')) == item) return a;
    }
    return nullptr;
}

// Waits until the document shows its running simulation as it goes (the pending delay has passed).
bool waitForPending(Document* d)
{
    return QTest::qWaitFor([d] { return d->isResultForSetup() && d->isSimulating() && d->result()->status == SimulationStatus::Running; }, 3000);
}

}  // namespace

class TestResponsive : public QObject {
    Q_OBJECT
private slots:
    void init() { window_ = std::make_unique<MainWindow>(); window_->resize(1024, 700); window_->show(); QVERIFY(QTest::qWaitForWindowExposed(window_.get())); }
    void cleanup() { window_.reset(); }

    void openingAnotherFileReplacesASlowRun();
    void editDuringASlowRunTakesEffect();
    void cancelKeepsAPartialLabelledResult();
    void quitDuringASlowRunEndsAtOnce();
    void quickEditsNeverShowThePendingState();

private:
    std::unique_ptr<MainWindow> window_;
};

void TestResponsive::openingAnotherFileReplacesASlowRun()
{
    Document* d = window_->document();
    d->waitForResult();
    std::vector<std::shared_ptr<const SimulationResult>> shown;
    connect(d, &Document::resultChanged, this, [&] { shown.push_back(d->result()); });
    QVERIFY(window_->openFile(slowShot()));
    QVERIFY(waitForPending(d));
    const std::size_t slowBalls = d->setup().balls.size();
    // The view shows the slow file's balls where they start, not the two-ball shot before it.
    QCOMPARE(window_->tableView()->scene().result->balls.size(), slowBalls);
    auto* overlay = window_->findChild<SimulationOverlay*>();
    QVERIFY(overlay);
    QVERIFY2(overlay->text().startsWith(QStringLiteral("Simulating")), qPrintable(overlay->text()));

    const QString straight = examplePath("straight-shot.json");
    QVERIFY(window_->openFile(straight));
    QVERIFY(QTest::qWaitFor([d] { return d->isResultCurrent(); }, 5000));
    // The second file's events, exactly as the simulator gives them; the first run never lands.
    const std::vector<Event> expected = eventsOf(straight);
    QCOMPARE(d->result()->events.size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) QCOMPARE(d->result()->events[k].time, expected[k].time);
    QVERIFY(d->result()->finished());
    for (const auto& r : shown)
        if (r->balls.size() == slowBalls) QVERIFY(r->status == SimulationStatus::Running);  // only its pending states
    QVERIFY(overlay->text().isEmpty());
}

void TestResponsive::editDuringASlowRunTakesEffect()
{
    Document* d = window_->document();
    QVERIFY(window_->openFile(slowShot()));
    QVERIFY(waitForPending(d));
    std::optional<CueStrike> shot = d->setup().shot;
    QVERIFY(shot);
    shot->speed = 0.2;  // a soft stroke away from the cluster: the run ends at once
    shot->headingDeg += 180.0;
    QVERIFY(d->setShot(shot, QStringLiteral("speed"), 0));
    QVERIFY(QTest::qWaitFor([d] { return d->isResultCurrent(); }, 5000));
    const SimulationResult& r = *d->result();
    QVERIFY(r.finished());
    QVERIFY(!r.events.empty());
    QVERIFY(r.events.front().kind == EventKind::CueStrike);
    // The strike of the edited shot: its speed is the new one.
    const int cue = r.ballIndex(shot->ball);
    QCOMPARE(r.events.front().balls[0], cue);
    QVERIFY(r.events.front().after[0].velocity.norm() < 1.0);
    // Undo brings the slow setup back, and it runs (shown as it goes) again.
    window_->document()->undoStack()->undo();
    QVERIFY(waitForPending(d));
    QString error;
    QCOMPARE(d->setup().shot->speed, io::loadSetup(slowShot(), &error)->shot->speed);
}

void TestResponsive::cancelKeepsAPartialLabelledResult()
{
    Document* d = window_->document();
    QVERIFY(window_->openFile(slowShot()));
    QVERIFY(waitForPending(d));
    QTest::qWait(400);  // some events in
    QAction* cancel = menuAction(window_->menuBar(), QStringLiteral("Playback"), QStringLiteral("Cancel Simulation"));
    QVERIFY(cancel);
    QVERIFY(cancel->isEnabled());
    QElapsedTimer clock;
    clock.start();
    cancel->trigger();
    QVERIFY(QTest::qWaitFor([d] { return !d->isSimulating(); }, 2000));
    qInfo("cancelled in %lld ms", static_cast<long long>(clock.elapsed()));
    const auto r = d->result();
    QVERIFY(r->status == SimulationStatus::Cancelled);
    QVERIFY(r->events.size() > 1);
    QVERIFY(r->endTime > 0.0);
    QVERIFY(d->isResultCurrent());
    QVERIFY(!cancel->isEnabled());
    // Every panel says it is partial.
    auto* overlay = window_->findChild<SimulationOverlay*>();
    QVERIFY2(overlay->text().startsWith(QStringLiteral("Stopped at t = ")), qPrintable(overlay->text()));
    auto* note = window_->findChild<QLabel*>(QStringLiteral("eventsRunNote"));
    QVERIFY(note && note->isVisible());
    QVERIFY2(note->text().contains(QStringLiteral("cancelled")), qPrintable(note->text()));
    auto* outcome = window_->findChild<QLabel*>(QStringLiteral("outcomeStatus"));
    QVERIFY(outcome);
    QVERIFY2(outcome->text().contains(QStringLiteral("So far")), qPrintable(outcome->text()));
    // The partial result is the simulator's own, event for event.
    QString error;
    const std::optional<Setup> s = io::loadSetup(slowShot(), &error);
    SimulationOptions o;
    o.maxEvents = static_cast<long long>(r->events.size());
    const SimulationResult prefix = simulate(*s, o);
    for (std::size_t k = 0; k < r->events.size(); ++k) QCOMPARE(r->events[k].time, prefix.events[k].time);
}

void TestResponsive::quitDuringASlowRunEndsAtOnce()
{
    Document* d = window_->document();
    QVERIFY(window_->openFile(slowShot()));
    QVERIFY(waitForPending(d));
    QAction* quit = menuAction(window_->menuBar(), QStringLiteral("File"), QStringLiteral("Quit"));
    QVERIFY(quit);
    QElapsedTimer clock;
    clock.start();
    quit->trigger();  // the document is unmodified: no question
    QVERIFY(!window_->isVisible());
    window_.reset();  // what follows the end of the event loop: the window and its document go
    QThreadPool::globalInstance()->waitForDone();
    const qint64 ms = clock.elapsed();
    qInfo("quit took %lld ms", static_cast<long long>(ms));
    QVERIFY2(ms < 2000, qPrintable(QStringLiteral("%1 ms").arg(ms)));
}

void TestResponsive::quickEditsNeverShowThePendingState()
{
    // A quick shot's result replaces the last one directly: no pending flash, no overlay.
    Document* d = window_->document();
    d->waitForResult();
    int running = 0;
    connect(d, &Document::resultChanged, this, [&] { running += d->result()->status == SimulationStatus::Running; });
    std::optional<CueStrike> shot = d->setup().shot;
    for (int i = 0; i < 5; ++i) {
        shot->speed = 1.0 + 0.25 * i;
        QVERIFY(d->setShot(shot, QStringLiteral("speed"), 0));
        d->waitForResult();
        QVERIFY(d->result()->finished());
    }
    QCOMPARE(running, 0);
    QVERIFY(window_->findChild<SimulationOverlay*>()->text().isEmpty());
}

QTEST_MAIN(TestResponsive)
#include "tst_responsive.moc"
