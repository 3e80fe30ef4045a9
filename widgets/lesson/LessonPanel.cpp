#include "LessonPanel.h"

#include "editor/Document.h"
#include "export/ShotFacts.h"

#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTimer>

namespace cuelab {

namespace {

// Commits the notes when they lose the focus.
class FocusOutFilter : public QObject {
public:
    FocusOutFilter(QObject* parent, std::function<void()> onFocusOut) : QObject(parent), f_(std::move(onFocusOut)) {}
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::FocusOut) f_();
        return QObject::eventFilter(watched, event);
    }

private:
    std::function<void()> f_;
};

}  // namespace

LessonPanel::LessonPanel(Document* document, QWidget* parent) : QWidget(parent), document_(document)
{
    name_ = new QLineEdit(this);
    name_->setObjectName(QStringLiteral("lessonName"));
    name_->setPlaceholderText(tr("Name of the shot"));
    name_->setToolTip(tr("The setup's name (saved in the file as \"name\")"));
    QFont big = name_->font();
    big.setBold(true);
    big.setPointSizeF(big.pointSizeF() * 1.2);
    name_->setFont(big);
    notes_ = new QPlainTextEdit(this);
    notes_->setObjectName(QStringLiteral("lessonNotes"));
    notes_->setPlaceholderText(tr("What this shot teaches: write the lesson here."));
    notes_->setToolTip(tr("The setup's notes (saved in the file as \"notes\"); each finished edit is one undo step"));
    stale_ = new QLabel(this);
    stale_->setObjectName(QStringLiteral("lessonStaleNotes"));
    stale_->setWordWrap(true);
    stale_->setTextFormat(Qt::PlainText);
    stale_->setStyleSheet(QStringLiteral("QLabel { color: #8a3b00; background: #fff1dc; border: 1px solid #e0a050; padding: 4px; }"));
    stale_->setToolTip(tr("The notes describe the shot as it was when they were written. Undo the changes, or edit the "
                          "notes to match the shot (that clears this flag). The lesson report prints the same warning."));
    stale_->hide();
    pause_ = new QTimer(this);
    pause_->setSingleShot(true);
    pause_->setInterval(1200);

    auto* form = new QFormLayout(this);
    form->setContentsMargins(4, 4, 4, 4);
    form->addRow(tr("Name"), name_);
    form->addRow(stale_);
    form->addRow(notes_);

    connect(name_, &QLineEdit::editingFinished, this, &LessonPanel::commit);
    connect(notes_, &QPlainTextEdit::textChanged, this, [this] {
        if (!loading_) pause_->start();
    });
    connect(pause_, &QTimer::timeout, this, &LessonPanel::commit);
    notes_->installEventFilter(new FocusOutFilter(this, [this] { commit(); }));
    if (document_) {
        connect(document_, &Document::setupChanged, this, &LessonPanel::load);
        connect(document_, &Document::documentReplaced, this, &LessonPanel::load);
    }
    load();
}

void LessonPanel::commit()
{
    pause_->stop();
    if (!document_ || loading_) return;
    document_->setLesson(name_->text().toStdString(), notes_->toPlainText().toStdString());
}

void LessonPanel::load()
{
    if (!document_) return;
    const QString name = QString::fromStdString(document_->setup().name);
    const QString notes = QString::fromStdString(document_->setup().notes);
    loading_ = true;
    if (name_->text() != name) name_->setText(name);
    if (notes_->toPlainText() != notes) notes_->setPlainText(notes);
    loading_ = false;
    flagStaleNotes();
}

void LessonPanel::flagStaleNotes()
{
    const QStringList changes = document_->setup().notes.empty()
                                    ? QStringList()
                                    : factChanges(document_->notesWrittenFor(), document_->setup());
    stale_->setVisible(!changes.isEmpty());
    if (!changes.isEmpty())
        stale_->setText(tr("These notes were written for the shot before these changes:\n• %1").arg(changes.join(QStringLiteral("\n• "))));
}

}  // namespace cuelab
