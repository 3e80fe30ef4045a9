#include "SimulationRunner.h"

#include <QMetaObject>

#include <atomic>
#include <chrono>
#include <exception>
#include <stop_token>

namespace cuelab {

struct SimulationRunner::Job {
    quint64 generation = 0;
    std::stop_source stop;
    std::atomic<bool> wantSnapshot{false};
    bool dropped = false;  // GUI thread only: a newer run replaced it, nothing of it is reported
};

SimulationRunner::SimulationRunner(QObject* parent) : QObject(parent)
{
    // Two threads: a run that was just stopped may still be answering its token (a step) when the
    // next one starts.
    pool_.setMaxThreadCount(2);
    pool_.setObjectName(QStringLiteral("cuelab-simulation"));
}

SimulationRunner::~SimulationRunner()
{
    // Every run stops before its next step; what is left is to wait for that step.
    if (current_) current_->stop.request_stop();
    current_.reset();
    waitForDone();
}

void SimulationRunner::waitForDone()
{
    // The stopped runs' own tokens were tripped when they were replaced or cancelled.
    pool_.waitForDone();
}

void SimulationRunner::start(const Setup& setup, quint64 generation)
{
    if (current_) {
        current_->dropped = true;
        current_->stop.request_stop();
    }
    auto job = std::make_shared<Job>();
    job->generation = generation;
    current_ = job;
    pool_.start([this, job, setup] {
        using Clock = std::chrono::steady_clock;
        SimulationOutcome out;
        out.generation = job->generation;
        if (job->stop.stop_requested()) {  // replaced before it began: nothing to report
            QMetaObject::invokeMethod(this, [this, job, out] { end(job, out); }, Qt::QueuedConnection);
            return;
        }
        // A copy of a long run's result costs time in proportion to its size: copies are spaced at
        // least ten times as far apart as the last one took, so that copying never takes more than a
        // tenth of the run.
        Clock::duration lastCopy{0};
        Clock::time_point lastCopyAt = Clock::now();
        SimulationOptions options;
        options.cancel = job->stop.get_token();
        options.progressInterval = 0.1;
        options.progress = [&](const SimulationResult& sofar, const SimulationProgress& p) {
            std::shared_ptr<const SimulationResult> copy;
            const Clock::time_point now = Clock::now();
            if (job->wantSnapshot.load() && now - lastCopyAt >= 10 * lastCopy) {
                job->wantSnapshot = false;
                copy = std::make_shared<SimulationResult>(sofar);
                lastCopyAt = Clock::now();
                lastCopy = lastCopyAt - now;
            }
            QMetaObject::invokeMethod(
                this, [this, job, events = p.events, time = p.time, copy] { report(job, events, time, copy); },
                Qt::QueuedConnection);
        };
        try {
            auto result = std::make_shared<SimulationResult>(simulate(setup, options));
            if (!result->finished()) out.error = QString::fromStdString(result->error);
            out.result = std::move(result);
        } catch (const std::exception& e) {
            out.error = tr("The simulation failed: %1").arg(QString::fromUtf8(e.what()));
        }
        QMetaObject::invokeMethod(this, [this, job, out] { end(job, out); }, Qt::QueuedConnection);
    });
}

void SimulationRunner::cancel()
{
    if (current_) current_->stop.request_stop();
}

void SimulationRunner::requestSnapshot()
{
    if (current_) current_->wantSnapshot = true;
}

void SimulationRunner::report(const std::shared_ptr<Job>& job, qint64 events, double time,
                              std::shared_ptr<const SimulationResult> copy)
{
    if (job != current_ || job->dropped) return;
    // (A cancelled run's last reports may still arrive: its result so far is still the newest.)
    emit progressed(job->generation, events, time);
    if (copy) emit snapshot(job->generation, std::move(copy));
}

void SimulationRunner::end(const std::shared_ptr<Job>& job, const SimulationOutcome& outcome)
{
    if (job != current_ || job->dropped) {
        if (outcome.result && outcome.result->finished()) emit superseded(outcome);
        return;
    }
    current_.reset();
    emit finished(outcome);
}

}  // namespace cuelab
