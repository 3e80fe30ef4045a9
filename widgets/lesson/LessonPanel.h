#pragma once
// The Lesson dock: the setup's name and notes (every bundled example is a written lesson), shown as
// soon as a file or example opens, and editable. A finished edit (the name's Return or leaving the
// field; the notes a moment after typing stops, or on leaving them) is one undo step through the
// Document, saved with the file. Notes that no longer match the setup (its shot or physics changed
// since they were written: ShotFacts.h) are flagged above them, with what changed.

#include <QWidget>

class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QTimer;

namespace cuelab {

class Document;

class LessonPanel : public QWidget {
    Q_OBJECT
public:
    explicit LessonPanel(Document* document, QWidget* parent = nullptr);

    QLineEdit* nameEdit() const { return name_; }
    QPlainTextEdit* notesEdit() const { return notes_; }
    QLabel* staleFlag() const { return stale_; }  // hidden while the notes match the setup

    // Applies what the fields hold to the document now (one undo step if anything changed).
    void commit();

private:
    void load();  // the fields from the document's setup
    void flagStaleNotes();

    Document* document_;
    QLineEdit* name_;
    QPlainTextEdit* notes_;
    QLabel* stale_;
    QTimer* pause_;
    bool loading_ = false;
};

}  // namespace cuelab
