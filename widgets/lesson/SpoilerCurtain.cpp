#include "SpoilerCurtain.h"

#include "editor/Document.h"

#include <QLabel>
#include <QVBoxLayout>

namespace cuelab {

SpoilerCurtain::SpoilerCurtain(Document* document, QWidget* content, QWidget* parent)
    : QStackedWidget(parent), document_(document), content_(content)
{
    auto* page = new QWidget(this);
    page->setObjectName(QStringLiteral("spoilerCurtain"));
    note_ = new QLabel(note(), page);
    note_->setWordWrap(true);
    note_->setAlignment(Qt::AlignCenter);
    auto* layout = new QVBoxLayout(page);
    layout->addStretch(1);
    layout->addWidget(note_);
    layout->addStretch(2);
    addWidget(content_);
    addWidget(page);
    // The horizon changes with resultChanged (Document::setHorizon), as does a new run that drops it.
    connect(document_, &Document::resultChanged, this, &SpoilerCurtain::follow);
    follow();
}

QString SpoilerCurtain::note()
{
    return tr("Hidden until you reveal the answer: this panel would show how the shot goes on.");
}

void SpoilerCurtain::follow()
{
    const bool drawn = document_->isWithholding();
    if (drawn == isDrawn()) return;
    setCurrentIndex(drawn ? 1 : 0);
    emit drawnChanged(drawn);
}

}  // namespace cuelab
