#pragma once
// Derives an event's explanation off the GUI thread (issues 39 and 41). A held group's derivation runs
// the shot again up to the event (core/physics/ContactTrace.h): as long as simulating up to it took,
// seconds late in a long shot, which the window must never wait for. One derivation at a time, the
// newest wins: starting one stops the one before it at once (the core's stop token: the run again
// answers within milliseconds) and drops its result. Destroying the runner stops and waits for it.

#include "Explanation.h"
#include "CueStrike.h"
#include "Simulation.h"

#include <QObject>
#include <QThreadPool>

#include <memory>
#include <optional>

namespace cuelab {

class ExplainRunner : public QObject {
    Q_OBJECT
public:
    explicit ExplainRunner(QObject* parent = nullptr);
    ~ExplainRunner() override;

    // Stops the derivation in progress (its result is never reported) and starts one of event `index`
    // of `result`, within the core's default budget for running the shot again (ExplainLimits).
    void start(std::shared_ptr<const SimulationResult> result, int index, const std::optional<CueStrike>& shot);
    // Stops the derivation in progress; nothing is reported.
    void cancel();
    bool isRunning() const { return current_ != nullptr; }

signals:
    // The current derivation's explanation; none when the core refused the event (then `error` says why).
    void finished(int index, std::shared_ptr<const explain::Explanation> explanation, const QString& error);

private:
    struct Job;
    void end(const std::shared_ptr<Job>& job, std::shared_ptr<const explain::Explanation> explanation,
             const QString& error);

    // One thread that lives as long as the runner: the core keeps the traces of the last result it ran
    // again per thread, so the events of one result after the first come at once.
    QThreadPool pool_;
    std::shared_ptr<Job> current_;  // the derivation whose result counts, null when idle
};

}  // namespace cuelab
