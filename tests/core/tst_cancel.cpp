// Issue 39: a run can be cancelled from another thread and reports its progress; a cancelled run keeps
// the events and motion it reached, marked unfinished, and they are the full run's events up to there.

#include "Racks.h"
#include "SetupFile.h"
#include "Simulation.h"
#include "SimulationChecks.h"

#include <QtTest>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

using namespace cuelab;
using namespace cuelab::testing;

namespace {

QString slowFixtures() { return QStringLiteral(CUELAB_SOURCE_DIR "/tests/core/fixtures/slow"); }

Setup loadFixture(const QString& name)
{
    QString error;
    std::optional<Setup> s = io::loadSetup(slowFixtures() + "/" + name, &error);
    if (!s) qFatal("%s", qPrintable(error));
    return *s;
}

bool sameEvent(const Event& a, const Event& b)
{
    if (a.kind != b.kind || a.time != b.time || a.balls != b.balls) return false;
    for (std::size_t k = 0; k < 2; ++k)
        if (a.after[k].position != b.after[k].position || a.after[k].velocity != b.after[k].velocity ||
            a.after[k].spin != b.after[k].spin || a.after[k].z != b.after[k].z || a.after[k].vz != b.after[k].vz)
            return false;
    return true;
}

}  // namespace

class TestCancel : public QObject {
    Q_OBJECT
private slots:
    void cancelledInProgressKeepsAPrefix();
    void progressIsMonotoneAndConsistent();
    void cancelFromAnotherThread_data();
    void cancelFromAnotherThread();
    void cancelBeforeTheFirstStep();
    void unfinishedStatuses();
};

void TestCancel::cancelledInProgressKeepsAPrefix()
{
    // A break: stopped from its own progress report once it has logged some events, the run ends
    // before its next step, Cancelled, with exactly the events of the full run up to there.
    const Setup setup = breakSetup(6.0);
    const SimulationResult full = simulate(setup);
    QVERIFY(full.finished());
    QVERIFY(full.events.size() > 40);

    std::stop_source stop;
    SimulationOptions options;
    options.cancel = stop.get_token();
    options.progressInterval = 0.0;  // a report at every 64th step
    long long seen = -1;
    options.progress = [&](const SimulationResult& sofar, const SimulationProgress& p) {
        QVERIFY(sofar.status == SimulationStatus::Running);
        if (p.events >= 20 && seen < 0) {
            seen = p.events;
            stop.request_stop();
        }
    };
    const SimulationResult cut = simulate(setup, options);
    QVERIFY(cut.status == SimulationStatus::Cancelled);
    QVERIFY(!cut.finished());
    QVERIFY(!cut.error.empty());
    QVERIFY(seen >= 20);
    QCOMPARE(static_cast<long long>(cut.events.size()), seen);  // not one step more
    for (std::size_t k = 0; k < cut.events.size(); ++k) QVERIFY2(sameEvent(cut.events[k], full.events[k]), qPrintable(QString::number(k)));
    QCOMPARE(cut.endTime, cut.events.back().time);
    // The motion up to the cut is the full run's.
    for (int i = 0; i < static_cast<int>(setup.balls.size()); ++i) {
        const BallState a = cut.stateAt(i, cut.endTime), b = full.stateAt(i, cut.endTime);
        QCOMPARE(a.position, b.position);
        QCOMPARE(a.velocity, b.velocity);
    }
}

void TestCancel::progressIsMonotoneAndConsistent()
{
    const Setup setup = breakSetup(6.0);
    SimulationOptions options;
    options.progressInterval = 0.0;
    const SimulationResult full = simulate(setup);
    long long calls = 0, lastEvents = -1;
    double lastTime = -1.0;
    options.progress = [&](const SimulationResult& sofar, const SimulationProgress& p) {
        ++calls;
        QVERIFY(p.events >= lastEvents);
        QVERIFY(p.time >= lastTime);
        QCOMPARE(static_cast<long long>(sofar.events.size()), p.events);
        QCOMPARE(sofar.endTime, p.time);
        QVERIFY(sofar.events.empty() || sofar.events.back().time == p.time);
        // The snapshot's events are the final ones.
        for (std::size_t k = 0; k < sofar.events.size(); ++k) QVERIFY(sameEvent(sofar.events[k], full.events[k]));
        lastEvents = p.events;
        lastTime = p.time;
    };
    const SimulationResult r = simulate(setup, options);
    QVERIFY(calls >= 2);  // before the first step, then as it goes
    QCOMPARE(r.events.size(), full.events.size());
    QVERIFY(r.finished());
}

void TestCancel::cancelFromAnotherThread_data()
{
    QTest::addColumn<QString>("file");
    for (const QString& f : QDir(slowFixtures()).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        QTest::newRow(qPrintable(f)) << f;
}

void TestCancel::cancelFromAnotherThread()
{
    // The long runs (fixtures/slow: setups that still cost the simulator seconds): a stop asked from
    // another thread a fifth of a second in is answered at once. (The latency itself is a benchmark figure,
    // `cuelab-bench --cancel`; the bound here only catches a run that no longer looks at its token.)
    QFETCH(QString, file);
    const Setup setup = loadFixture(file);
    std::stop_source stop;
    SimulationOptions options;
    options.cancel = stop.get_token();
    std::atomic<bool> done{false};
    SimulationResult r;
    std::thread worker([&] {
        r = simulate(setup, options);
        done = true;
    });
    using Clock = std::chrono::steady_clock;
    const auto begun = Clock::now();
    while (!done && Clock::now() - begun < std::chrono::milliseconds(200)) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const bool finishedFirst = done;
    const auto asked = Clock::now();
    stop.request_stop();
    worker.join();
    const double latency = std::chrono::duration<double>(Clock::now() - asked).count();
    if (finishedFirst) {
        QVERIFY(r.finished());  // fast now: then it must have come to rest by itself
        return;
    }
    qInfo("%s: cancelled after %lld events at t = %.6f s, %.2f ms after the request", qPrintable(file),
          static_cast<long long>(r.events.size()), r.endTime, 1e3 * latency);
    QVERIFY2(r.status == SimulationStatus::Cancelled || r.finished(), r.error.c_str());
    QVERIFY2(latency < 1.0, qPrintable(QStringLiteral("%1 s").arg(latency)));
    if (r.status == SimulationStatus::Cancelled) {
        QVERIFY(!r.error.empty());
        const std::string problem = timelineProblem(r);
        QVERIFY2(problem.empty(), problem.c_str());
    }
}

void TestCancel::cancelBeforeTheFirstStep()
{
    // Asked before it starts, the run still places the balls and strikes (t = 0), then stops.
    std::stop_source stop;
    stop.request_stop();
    SimulationOptions options;
    options.cancel = stop.get_token();
    const Setup setup = breakSetup(6.0);
    const SimulationResult r = simulate(setup, options);
    QVERIFY(r.status == SimulationStatus::Cancelled);
    QCOMPARE(r.endTime, 0.0);
    QCOMPARE(r.timelines.size(), setup.balls.size());
    for (const auto& timeline : r.timelines) QVERIFY(!timeline.empty());
}

void TestCancel::unfinishedStatuses()
{
    QVERIFY(isFinished(SimulationStatus::AllAtRest));
    QVERIFY(isFinished(SimulationStatus::ReachedUntil));
    QVERIFY(!isFinished(SimulationStatus::EventLimit));
    QVERIFY(!isFinished(SimulationStatus::Cancelled));
    QVERIFY(!isFinished(SimulationStatus::Running));
    // The event cap is the same mechanism: the events up to the cut, unfinished, with a reason.
    SimulationOptions options;
    options.maxEvents = 10;
    const SimulationResult r = simulate(breakSetup(6.0), options);
    QVERIFY(r.status == SimulationStatus::EventLimit);
    QCOMPARE(r.events.size(), std::size_t(10));
    QCOMPARE(r.endTime, r.events.back().time);
    QVERIFY(!r.error.empty());
}

QTEST_APPLESS_MAIN(TestCancel)
#include "tst_cancel.moc"
