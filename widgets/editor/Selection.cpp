#include "Selection.h"

namespace cuelab {

void Selection::selectBall(int index)
{
    if (index < 0) index = -1;
    const bool ballChangedNow = index != ball_;
    ball_ = index;
    if (index >= 0 && event_ >= 0) {
        event_ = -1;
        emit eventChanged(-1);
    }
    if (ballChangedNow) emit ballChanged(index);
    if (index >= 0) setSubject(Subject::Ball);
    else if (subject_ == Subject::Ball) setSubject(Subject::None);
}

void Selection::selectEvent(int index)
{
    if (index < 0) index = -1;
    // Choosing an event again is a request to go to it again (the transport may have moved since):
    // it emits even when the index is the same.
    const bool emitNow = index != event_ || index >= 0;
    event_ = index;
    if (emitNow) emit eventChanged(index);
    if (index >= 0) setSubject(Subject::Event);
    else if (subject_ == Subject::Event) setSubject(Subject::None);
}

void Selection::clear()
{
    selectBall(-1);
    selectEvent(-1);
}

void Selection::setSubject(Subject subject)
{
    if (subject == subject_) return;
    subject_ = subject;
    emit subjectChanged();
}

}  // namespace cuelab
