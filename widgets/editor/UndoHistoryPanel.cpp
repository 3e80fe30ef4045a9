#include "UndoHistoryPanel.h"

#include "Document.h"

#include <QUndoView>
#include <QVBoxLayout>

namespace cuelab {

UndoHistoryPanel::UndoHistoryPanel(Document* document, QWidget* parent)
    : QWidget(parent), document_(document), view_(new QUndoView(document->undoStack(), this))
{
    view_->setObjectName(QStringLiteral("undoHistory"));
    view_->setToolTip(tr("Every edit since the setup was opened; click one to go back (or forward) to it"));
    view_->setAlternatingRowColors(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(view_);
    connect(document_, &Document::documentReplaced, this, &UndoHistoryPanel::updateEmptyLabel);
    connect(document_, &Document::filePathChanged, this, &UndoHistoryPanel::updateEmptyLabel);
    updateEmptyLabel();
}

void UndoHistoryPanel::updateEmptyLabel()
{
    // The first row: the state before any edit, named after the document.
    view_->setEmptyLabel(tr("Opened %1").arg(document_->displayName()));
}

}  // namespace cuelab
