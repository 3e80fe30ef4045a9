#include "ExplainRunner.h"

#include "Explain.h"

#include <QMetaObject>

#include <exception>
#include <stop_token>

namespace cuelab {

struct ExplainRunner::Job {
    std::stop_source stop;
    int index = -1;
};

ExplainRunner::ExplainRunner(QObject* parent) : QObject(parent)
{
    pool_.setMaxThreadCount(1);
    pool_.setExpiryTimeout(-1);
    pool_.setObjectName(QStringLiteral("cuelab-explain"));
}

ExplainRunner::~ExplainRunner()
{
    cancel();
    pool_.waitForDone();
}

void ExplainRunner::cancel()
{
    if (current_) current_->stop.request_stop();
    current_.reset();
}

void ExplainRunner::start(std::shared_ptr<const SimulationResult> result, int index, const std::optional<CueStrike>& shot)
{
    cancel();
    auto job = std::make_shared<Job>();
    job->index = index;
    current_ = job;
    pool_.start([this, job, result = std::move(result), shot] {
        // (Stopped while it waited for the one before it to wind down: nothing to do.)
        if (job->stop.stop_requested()) return;
        std::shared_ptr<const explain::Explanation> explanation;
        QString error;
        try {
            explain::ExplainLimits limits;
            limits.stop = job->stop.get_token();
            explanation = std::make_shared<const explain::Explanation>(explain::explain(*result, job->index, shot, limits));
        } catch (const std::exception& e) {
            error = QString::fromUtf8(e.what());
        }
        if (job->stop.stop_requested()) return;
        QMetaObject::invokeMethod(
            this, [this, job, explanation, error] { end(job, explanation, error); }, Qt::QueuedConnection);
    });
}

void ExplainRunner::end(const std::shared_ptr<Job>& job, std::shared_ptr<const explain::Explanation> explanation,
                        const QString& error)
{
    if (job != current_) return;  // (replaced or cancelled after it finished: a stale derivation)
    current_.reset();
    emit finished(job->index, std::move(explanation), error);
}

}  // namespace cuelab
