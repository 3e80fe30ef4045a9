#pragma once
// Runs a comparison (core/compare) in the background: the exact run, the chosen engine, the
// divergence. A new request drops the one in progress (it is cancelled at its next progress check
// and its result never shown), so changing a step while a slow run is busy never freezes the window
// and never shows a stale answer.

#include "Divergence.h"
#include "Setup.h"

#include <QObject>

#include <atomic>
#include <memory>
#include <optional>

class QTimer;
template <typename T>
class QFutureWatcher;

namespace cuelab {

struct CompareOutcome {
    quint64 generation = 0;
    std::shared_ptr<const compare::Comparison> comparison;  // null when cancelled or failed
    QString error;
};

class CompareRunner : public QObject {
    Q_OBJECT
public:
    explicit CompareRunner(QObject* parent = nullptr);
    ~CompareRunner() override;

    // Starts comparing `setup` under `settings` (checked with compare::checkSettings by the caller).
    void run(const Setup& setup, const compare::EngineSettings& settings);
    bool isRunning() const { return busy_ || pending_.has_value(); }
    // The latest finished comparison of the latest request (null before the first).
    std::shared_ptr<const compare::Comparison> result() const { return result_; }
    int progressPercent() const { return progress_->load(); }

    // Blocks until nothing is running (tests).
    void waitForIdle();

signals:
    void runningChanged(bool running);
    void progressChanged(int percent);
    void finished();                     // result() holds the new comparison
    void failed(const QString& message);

private:
    struct Request {
        Setup setup;
        compare::EngineSettings settings;
    };
    void startPending();
    void onFinished();

    QFutureWatcher<CompareOutcome>* watcher_;
    QTimer* progressTimer_;
    std::optional<Request> pending_;
    bool busy_ = false;
    quint64 generation_ = 0;
    std::shared_ptr<std::atomic<quint64>> current_;
    std::shared_ptr<std::atomic<int>> progress_;
    std::shared_ptr<const compare::Comparison> result_;
    int lastReported_ = -1;
};

}  // namespace cuelab
