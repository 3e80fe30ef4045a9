#pragma once
// The Lesson dock: the setup's name and notes (every bundled example is a written lesson), shown as
// soon as a file or example opens, and editable. A finished edit (the name's Return or leaving the
// field; the notes a moment after typing stops, or on leaving them) is one undo step through the
// Document, saved with the file.

#include <QWidget>

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

    // Applies what the fields hold to the document now (one undo step if anything changed).
    void commit();

private:
    void load();  // the fields from the document's setup

    Document* document_;
    QLineEdit* name_;
    QPlainTextEdit* notes_;
    QTimer* pause_;
    bool loading_ = false;
};

}  // namespace cuelab
