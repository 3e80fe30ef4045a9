#include "AnalysisJob.h"

#include <QMetaObject>
#include <QPointer>

#include <atomic>
#include <chrono>

namespace cuelab {

AnalysisJob::AnalysisJob(QObject* parent) : QObject(parent) {}

AnalysisJob::~AnalysisJob() { stopWorker(); }

void AnalysisJob::stopWorker()
{
    if (worker_.joinable()) {
        worker_.request_stop();
        worker_.join();
    }
}

void AnalysisJob::cancel()
{
    if (!running_) return;
    ++generation_;  // whatever the worker still posts is dropped
    stopWorker();
    running_ = false;
    emit runningChanged(false);
    emit finished(true);
}

void AnalysisJob::start(std::function<void(Context&)> work)
{
    if (running_) cancel();
    stopWorker();
    const quint64 generation = ++generation_;
    running_ = true;
    emit runningChanged(true);

    QPointer<AnalysisJob> self(this);
    // Progress is posted at most every 50 ms: a map of 10 000 cells must not flood the event loop.
    auto lastProgress = std::make_shared<std::atomic<long long>>(0);
    worker_ = std::jthread([self, generation, lastProgress, work = std::move(work)](std::stop_token stop) {
        Context context;
        context.stop = stop;
        context.post = [self, generation](std::function<void()> f) {
            QMetaObject::invokeMethod(
                self.data(),
                [self, generation, f = std::move(f)] {
                    if (self && self->generation_ == generation) f();
                },
                Qt::QueuedConnection);
        };
        // Progress goes through the same generation check as results.
        context.progress = [&context, lastProgress, self](long long done, long long total) {
            const long long now = std::chrono::duration_cast<std::chrono::milliseconds>(
                                      std::chrono::steady_clock::now().time_since_epoch())
                                      .count();
            if (done < total && now - lastProgress->load() < 50) return;
            lastProgress->store(now);
            context.post([self, done, total] {
                if (self) emit self->progressChanged(done, total);
            });
        };
        work(context);
        const bool cancelled = stop.stop_requested();
        context.post([self, cancelled] {
            if (!self) return;
            self->running_ = false;
            emit self->runningChanged(false);
            emit self->finished(cancelled);
        });
    });
}

}  // namespace cuelab
