#include "CompareRunner.h"

#include <QCoreApplication>
#include <QFutureWatcher>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <exception>

namespace cuelab {

namespace {

CompareOutcome runComparison(Setup setup, compare::EngineSettings settings, quint64 generation,
                             std::shared_ptr<std::atomic<quint64>> current, std::shared_ptr<std::atomic<int>> progress)
{
    CompareOutcome out;
    out.generation = generation;
    try {
        // compareEngines (core/compare) in its two parts, to report progress and stop in between.
        // (A long exact run stops within a step once a newer request or the window's end replaces it.)
        compare::EngineRun exact = compare::exactRunFor(setup, settings, [&](double) { return current->load() == generation; });
        if (exact.cancelled || current->load() != generation) return out;
        progress->store(5);
        // The other engines usually run a little longer than the exact one (no slide phase).
        const double expected = std::max(1.0, 1.3 * exact.endTime);
        const compare::Progress report = [&](double t) {
            progress->store(std::clamp(5 + static_cast<int>(90.0 * t / expected), 5, 95));
            return current->load() == generation;
        };
        auto c = std::make_shared<compare::Comparison>(compare::compareWith(setup, settings, std::move(exact), report));
        if (c->run.cancelled || current->load() != generation) return out;
        progress->store(100);
        out.comparison = std::move(c);
    } catch (const std::exception& e) {
        out.error = QString::fromUtf8(e.what());
    }
    return out;
}

}  // namespace

CompareRunner::CompareRunner(QObject* parent)
    : QObject(parent),
      watcher_(new QFutureWatcher<CompareOutcome>(this)),
      progressTimer_(new QTimer(this)),
      current_(std::make_shared<std::atomic<quint64>>(0)),
      progress_(std::make_shared<std::atomic<int>>(0))
{
    connect(watcher_, &QFutureWatcher<CompareOutcome>::finished, this, &CompareRunner::onFinished);
    progressTimer_->setInterval(100);
    connect(progressTimer_, &QTimer::timeout, this, [this] {
        const int p = progress_->load();
        if (p != lastReported_) emit progressChanged(lastReported_ = p);
    });
}

CompareRunner::~CompareRunner()
{
    current_->store(0);  // cancels a run in progress at its next check
    watcher_->waitForFinished();
}

void CompareRunner::run(const Setup& setup, const compare::EngineSettings& settings)
{
    const bool wasRunning = isRunning();
    pending_ = Request{setup, settings};
    current_->store(++generation_);
    if (!busy_) startPending();
    if (!wasRunning) emit runningChanged(true);
}

void CompareRunner::startPending()
{
    if (!pending_) return;
    Request r = std::move(*pending_);
    pending_.reset();
    busy_ = true;
    progress_->store(0);
    lastReported_ = -1;
    progressTimer_->start();
    watcher_->setFuture(QtConcurrent::run(runComparison, std::move(r.setup), r.settings, generation_, current_, progress_));
}

void CompareRunner::onFinished()
{
    busy_ = false;
    progressTimer_->stop();
    const CompareOutcome out = watcher_->result();
    const bool latest = out.generation == generation_;
    if (pending_) {
        startPending();  // a newer request waited for this (now stale) run
        return;
    }
    emit runningChanged(false);
    if (!latest) return;
    if (!out.error.isEmpty()) {
        emit failed(out.error);
        return;
    }
    if (!out.comparison) return;
    result_ = out.comparison;
    emit progressChanged(100);
    emit finished();
}

void CompareRunner::waitForIdle()
{
    while (isRunning()) {
        watcher_->waitForFinished();
        QCoreApplication::processEvents();  // delivers finished(), which may start the pending request
    }
}

}  // namespace cuelab
