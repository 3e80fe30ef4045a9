#pragma once
// Input like a good Qt program, for every editor of the window (an event filter on the application):
//
// - The mouse wheel changes a slider, a spin box or a combo box only when it has the keyboard focus;
//   over one without focus the wheel scrolls whatever holds it (a dock's scroll area), so scrolling
//   the Shot panel never changes the shot. Such editors take the focus by click or Tab, not by the
//   wheel (Qt::StrongFocus instead of Qt::WheelFocus).
// - Undo and Redo go to the document once a field's edit is committed (Enter, or the value set
//   from the document): a line edit or spin box that keeps the focus after Enter no longer swallows
//   Ctrl+Z for its own, empty, typing history. While the field holds uncommitted typing, Ctrl+Z
//   undoes the typing, as in any text field.
// - Page Up, Page Down, Home and End scroll a read-only text that has the focus (Explain, the
//   lesson notes, the help); elsewhere they stay the transport's keys (previous and next event,
//   start and end).

#include <QObject>

class QLineEdit;
class QScrollBar;
class QWidget;

namespace cuelab {

class InputGuard : public QObject {
    Q_OBJECT
public:
    // Guards the editors inside `window` (and its docks, floating or not); installs itself on the
    // application.
    explicit InputGuard(QWidget* window);

    // Whether the wheel may change `editor` (a slider, spin box or combo box): only with the focus.
    static bool wheelMayChange(const QWidget* editor);
    static bool isWheelGuarded(const QWidget* widget);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool guards(const QWidget* widget) const;
    static QLineEdit* textOf(QObject* editor);
    // The scroll bar a page key moves when `widget` (a read-only text) has the focus, else null.
    static QScrollBar* pagedBy(QObject* widget, int key);

    QWidget* window_;
};

}  // namespace cuelab
