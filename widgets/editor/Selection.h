#pragma once
// What the user has selected: a ball, an event, or nothing. One object the window owns; panels,
// the view and feature docks read it and listen to it instead of asking the window.
//
// Selecting a ball clears the selected event; selecting an event keeps the selected ball (the view
// still marks it) but makes the event the subject the Inspector shows (subject()). selectBall emits
// only when the value changes; selectEvent(i >= 0) always emits, since choosing an event again means
// "go to it again".

#include <QObject>

namespace cuelab {

class Selection : public QObject {
    Q_OBJECT
public:
    enum class Subject { None, Ball, Event };

    explicit Selection(QObject* parent = nullptr) : QObject(parent) {}

    int ball() const { return ball_; }    // ball index, or -1
    int event() const { return event_; }  // event index into the current result, or -1
    Subject subject() const { return subject_; }

    // -1 clears.
    void selectBall(int index);
    void selectEvent(int index);
    void clear();

signals:
    void ballChanged(int index);
    void eventChanged(int index);
    void subjectChanged();

private:
    void setSubject(Subject subject);

    int ball_ = -1;
    int event_ = -1;
    Subject subject_ = Subject::None;
};

}  // namespace cuelab
