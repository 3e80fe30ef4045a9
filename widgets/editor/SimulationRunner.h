#pragma once
// Runs the document's simulations off the GUI thread (issue 39): one run per setup generation, the
// newest one wins. Starting a run stops the one before it at once (the core's cancel token: it
// answers before its next step, within milliseconds whatever the shot), and the stopped run's result
// is dropped. A run reports its progress as it goes and, when asked, a copy of its result so far, so
// that a long shot can be shown and stepped through while it is computed. Destroying the runner stops
// every run and waits for them (milliseconds), so that quitting quits.

#include "Setup.h"
#include "Simulation.h"

#include <QObject>
#include <QString>
#include <QThreadPool>

#include <memory>

namespace cuelab {

struct SimulationOutcome {
    std::shared_ptr<const SimulationResult> result;  // null when the simulator threw
    QString error;                                   // why it failed, was cut short or cancelled
    quint64 generation = 0;                          // which setup it belongs to
};

class SimulationRunner : public QObject {
    Q_OBJECT
public:
    explicit SimulationRunner(QObject* parent = nullptr);
    ~SimulationRunner() override;

    // Stops the run in progress (its result will not be reported) and starts one for `setup`.
    void start(const Setup& setup, quint64 generation);
    // Stops the run in progress: it reports finished() with what it had computed (status Cancelled).
    void cancel();
    // The run's next progress report carries a copy of its result so far (snapshot()). A request made
    // while a copy is on its way is merged with it.
    void requestSnapshot();
    bool isRunning() const { return current_ != nullptr; }
    // Blocks until no run is left (tests, and the destructor).
    void waitForDone();

signals:
    // The current run's progress: events so far and the simulated time reached (s).
    void progressed(quint64 generation, qint64 events, double time);
    // A copy of the current run's result so far (status Running), after requestSnapshot().
    void snapshot(quint64 generation, std::shared_ptr<const SimulationResult> sofar);
    // The current run ended: finished, cut short, cancelled or failed.
    void finished(const SimulationOutcome& outcome);
    // A run that a newer one replaced had already finished (a whole run, of an older setup): the
    // document may show it while a drag goes on (the newest run's result follows).
    void superseded(const SimulationOutcome& outcome);

private:
    struct Job;
    void report(const std::shared_ptr<Job>& job, qint64 events, double time, std::shared_ptr<const SimulationResult> copy);
    void end(const std::shared_ptr<Job>& job, const SimulationOutcome& outcome);

    QThreadPool pool_;              // the simulator's own threads: other background work cannot hold it up
    std::shared_ptr<Job> current_;  // the run whose results count, null when idle
};

}  // namespace cuelab
