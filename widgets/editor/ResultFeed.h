#pragma once
// Hands the document's results to a panel, sparing the GUI thread while a drag goes on (issue 39).
//
// A drag (a ball, the tip, a slider: edits that merge into one undo step) publishes a whole new result
// many times a second, and the table view shows each of them. A panel that lays out tables, charts or
// text for every result (Events, Plots, Outcome, Balls, Analysis, Explain) would take the frame time
// from the view. A ResultFeed calls its panel at once on every result outside a drag, and at most once
// per interval during one (the latest result; none is skipped at the end): when the drag ends, a
// result still owed is delivered at once.

#include <QObject>

#include <functional>

class QTimer;

namespace cuelab {

class Document;

class ResultFeed : public QObject {
    Q_OBJECT
public:
    static constexpr int kDragIntervalMs = 200;

    // `update` runs on the GUI thread with `context` alive (it is the feed's parent); it reads the
    // document's result itself.
    ResultFeed(Document* document, QObject* context, std::function<void()> update, int intervalMs = kDragIntervalMs);

    // Connects `update` to `document`'s results through a new feed owned by `context`.
    static ResultFeed* follow(Document* document, QObject* context, std::function<void()> update);

    bool owed() const;  // a result arrived during the drag that `update` has not seen yet

private:
    void onResult();
    void deliver();

    Document* document_;
    std::function<void()> update_;
    QTimer* timer_;
    bool owed_ = false;
};

}  // namespace cuelab
