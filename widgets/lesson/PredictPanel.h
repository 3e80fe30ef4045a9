#pragma once
// The Predict dock (issue 22, item 4): the lesson's predict-then-reveal questions, editable (each
// change one undo step, saved with the file as "lesson": {"questions": ...}), and the mode itself:
// Start plays the shot and stops before each question's event; the student drags an arrow from each
// asked ball in the table view; Reveal shows where the balls went, with each guess's angle error and
// score, here and in the view (PredictSession).

#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;

namespace cuelab {

class Document;
class Playback;
class PredictSession;
class Selection;
class TableView;

class PredictPanel : public QWidget {
    Q_OBJECT
public:
    PredictPanel(Document* document, Playback* playback, Selection* selection, TableView* view, QWidget* parent = nullptr);

    PredictSession* session() const { return session_; }
    QTableWidget* questionsTable() const { return questions_; }
    QTableWidget* resultsTable() const { return results_; }
    QPushButton* startButton() const { return start_; }
    QPushButton* revealButton() const { return reveal_; }
    QLabel* statusLabel() const { return status_; }

    // Adds a question before the selected event (or, with none selected, the first collision), its
    // balls the event's own: one undo step.
    void addQuestion();
    void removeQuestion();  // the selected row's: one undo step

private:
    void loadQuestions();
    void commitCell(int row, int column);
    void toggleSession();
    void refreshMode();
    void refreshResults();

    Document* document_;
    Selection* selection_;
    PredictSession* session_;
    QTableWidget* questions_;
    QPushButton* add_;
    QPushButton* remove_;
    QPushButton* start_;
    QPushButton* reveal_;
    QLabel* status_;
    QTableWidget* results_;
    bool loading_ = false;
};

}  // namespace cuelab
