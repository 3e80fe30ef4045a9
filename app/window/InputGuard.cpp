#include "InputGuard.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>
#include <QPointer>
#include <QScrollBar>
#include <QTimer>
#include <QWheelEvent>

namespace cuelab {

InputGuard::InputGuard(QWidget* window) : QObject(window), window_(window)
{
    qApp->installEventFilter(this);
}

bool InputGuard::isWheelGuarded(const QWidget* widget)
{
    // A scroll bar is a slider too, but scrolling is what the wheel is for: a list's or a text's
    // scroll bar (to which its viewport hands the wheel) scrolls without the focus (issue 44).
    if (qobject_cast<const QScrollBar*>(widget)) return false;
    return qobject_cast<const QAbstractSlider*>(widget) || qobject_cast<const QAbstractSpinBox*>(widget) ||
           qobject_cast<const QComboBox*>(widget);
}

bool InputGuard::wheelMayChange(const QWidget* editor) { return !isWheelGuarded(editor) || editor->hasFocus(); }

bool InputGuard::guards(const QWidget* widget) const
{
    // The window's own widgets and those of its docks, also when a dock floats (a window of its own).
    for (const QWidget* w = widget; w; w = w->parentWidget())
        if (w == window_) return true;
    return false;
}

QLineEdit* InputGuard::textOf(QObject* editor)
{
    if (auto* line = qobject_cast<QLineEdit*>(editor)) return line;
    if (auto* spin = qobject_cast<QAbstractSpinBox*>(editor)) return spin->findChild<QLineEdit*>();
    return nullptr;
}

QScrollBar* InputGuard::pagedBy(QObject* widget, int key)
{
    if (key != Qt::Key_PageUp && key != Qt::Key_PageDown && key != Qt::Key_Home && key != Qt::Key_End) return nullptr;
    auto* area = qobject_cast<QAbstractScrollArea*>(widget);
    const auto* rich = qobject_cast<QTextEdit*>(widget);
    const auto* plain = qobject_cast<QPlainTextEdit*>(widget);
    if (!area || !((rich && rich->isReadOnly()) || (plain && plain->isReadOnly()))) return nullptr;
    QScrollBar* bar = area->verticalScrollBar();
    return bar && bar->maximum() > bar->minimum() ? bar : nullptr;
}

bool InputGuard::eventFilter(QObject* watched, QEvent* event)
{
    if (!watched->isWidgetType()) return false;
    auto* widget = static_cast<QWidget*>(watched);
    switch (event->type()) {
    case QEvent::Polish:
        // Before the first wheel event: the wheel must not give these editors the focus either.
        if (isWheelGuarded(widget) && widget->focusPolicy() == Qt::WheelFocus && guards(widget))
            widget->setFocusPolicy(Qt::StrongFocus);
        break;
    case QEvent::Wheel:
        if (!wheelMayChange(widget) && guards(widget)) {
            // Not for this editor: the event goes on to its parents (a scroll area scrolls).
            event->ignore();
            return true;
        }
        break;
    case QEvent::KeyPress: {
        auto* press = static_cast<QKeyEvent*>(event);
        if (press->modifiers() == Qt::NoModifier && guards(widget))
            if (QScrollBar* bar = pagedBy(widget, press->key())) {
                const int key = press->key();
                bar->triggerAction(key == Qt::Key_PageUp     ? QAbstractSlider::SliderPageStepSub
                                   : key == Qt::Key_PageDown ? QAbstractSlider::SliderPageStepAdd
                                   : key == Qt::Key_Home     ? QAbstractSlider::SliderToMinimum
                                                             : QAbstractSlider::SliderToMaximum);
                return true;
            }
        // Enter commits the field: its text is then the document's, and Ctrl+Z belongs to the document.
        const int key = static_cast<QKeyEvent*>(event)->key();
        if ((key == Qt::Key_Return || key == Qt::Key_Enter) && guards(widget))
            if (QLineEdit* line = textOf(widget))
                QTimer::singleShot(0, line, [p = QPointer<QLineEdit>(line)] {
                    if (p) p->setModified(false);
                });
        break;
    }
    case QEvent::ShortcutOverride: {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->modifiers() == Qt::NoModifier && guards(widget) && pagedBy(widget, key->key())) {
            // A focused text's page keys scroll it: not the transport's shortcuts.
            event->accept();
            return true;
        }
        const bool undoOrRedo = key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo) ||
                                key->keyCombination() == QKeyCombination(Qt::ControlModifier | Qt::ShiftModifier, Qt::Key_Z) ||
                                key->keyCombination() == QKeyCombination(Qt::ControlModifier, Qt::Key_Y);
        if (!undoOrRedo || !guards(widget)) break;
        const QLineEdit* line = textOf(widget);
        if (line && !line->isModified()) {
            // Nothing typed since the last commit: not the field's shortcut, the window's.
            event->ignore();
            return true;
        }
        break;
    }
    default: break;
    }
    return false;
}

}  // namespace cuelab
