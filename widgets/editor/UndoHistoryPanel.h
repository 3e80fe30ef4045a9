#pragma once
// The undo history dock: every edit of the document as a list (QUndoView on the document's undo
// stack). Clicking an entry undoes or redoes up to it; the first entry is the setup as opened.

#include <QWidget>

class QUndoView;

namespace cuelab {

class Document;

class UndoHistoryPanel : public QWidget {
    Q_OBJECT
public:
    explicit UndoHistoryPanel(Document* document, QWidget* parent = nullptr);

    QUndoView* view() const { return view_; }

private:
    void updateEmptyLabel();

    Document* document_;
    QUndoView* view_;
};

}  // namespace cuelab
