#pragma once
// Runs one analysis (tolerance scans or a map, core/analysis) on a background thread and hands its
// results to the GUI thread as they come, in batches, so that the window never waits. A job belongs
// to one setup: start() of a new job or cancel() stops the old one, and a batch that arrives from a
// stopped job is dropped (each carries its job's generation).

#include <QObject>

#include <functional>
#include <memory>
#include <mutex>
#include <stop_token>
#include <thread>
#include <vector>

namespace cuelab {

class AnalysisJob : public QObject {
    Q_OBJECT
public:
    explicit AnalysisJob(QObject* parent = nullptr);
    ~AnalysisJob() override;  // stops and joins the worker

    // What the worker gets: its stop token, a way to post a result to the GUI thread (thread-safe;
    // the function runs there, later, unless the job was stopped meanwhile) and to report progress.
    struct Context {
        std::stop_token stop;
        std::function<void(std::function<void()>)> post;
        std::function<void(long long done, long long total)> progress;
    };

    // Stops any running work and starts `work` on a new thread.
    void start(std::function<void(Context&)> work);
    void cancel();
    bool isRunning() const { return running_; }
    quint64 generation() const { return generation_; }

signals:
    void progressChanged(long long done, long long total);
    void runningChanged(bool running);
    void finished(bool cancelled);

private:
    void stopWorker();

    std::jthread worker_;
    quint64 generation_ = 0;
    bool running_ = false;
};

}  // namespace cuelab
