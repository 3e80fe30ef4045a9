#include "ResultFeed.h"

#include "Document.h"

#include <QTimer>

namespace cuelab {

ResultFeed::ResultFeed(Document* document, QObject* context, std::function<void()> update, int intervalMs)
    : QObject(context), document_(document), update_(std::move(update)), timer_(new QTimer(this))
{
    timer_->setSingleShot(true);
    timer_->setInterval(intervalMs);
    QObject::connect(timer_, &QTimer::timeout, this, [this] {
        if (owed_) deliver();
    });
    QObject::connect(document_, &Document::resultChanged, this, &ResultFeed::onResult);
    QObject::connect(document_, &Document::dragFinished, this, [this] {
        if (owed_) deliver();
    });
}

ResultFeed* ResultFeed::follow(Document* document, QObject* context, std::function<void()> update)
{
    return new ResultFeed(document, context, std::move(update));
}

bool ResultFeed::owed() const { return owed_; }

void ResultFeed::onResult()
{
    if (!document_->isDragging()) {
        deliver();
        return;
    }
    // In a drag: the first result of a quiet spell at once (the panel follows the drag's start), then
    // at most one per interval.
    owed_ = true;
    if (!timer_->isActive()) {
        deliver();
        timer_->start();
    }
}

void ResultFeed::deliver()
{
    owed_ = false;
    update_();
}

}  // namespace cuelab
