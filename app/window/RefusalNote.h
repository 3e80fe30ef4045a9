#pragma once
// A refused edit is said beside the field that made it: the validator's reason (which the status bar
// also carries) in a note just under the field that has the focus (a list's edited cell), until the next edit, a new focus
// or a few seconds pass. Fields that say their refusals themselves (the Balls editor, marked with the
// property "saysRefusals") and edits from the table view (a drag: the status bar alone) get no note.

#include <QLabel>
#include <QPointer>
#include <QTimer>

namespace cuelab {

class RefusalNote : public QLabel {
    Q_OBJECT
public:
    static constexpr int kShownMs = 8000;

    explicit RefusalNote(QWidget* window);

    // Says `message` beside the window's focused field, if a field of a dock has the focus. Returns
    // whether the note is shown.
    bool say(const QString& message);
    QWidget* field() const { return field_; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void place();

    QWidget* window_;
    QPointer<QWidget> field_;
    QRect cell_;  // in field_'s coordinates: the edited cell of a list, else empty
    QTimer hide_;
};

}  // namespace cuelab
