#include "RefusalNote.h"

#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QDockWidget>
#include <QEvent>

#include <algorithm>

namespace cuelab {

RefusalNote::RefusalNote(QWidget* window) : QLabel(window), window_(window)
{
    setObjectName(QStringLiteral("refusalNote"));
    setWordWrap(true);
    setAutoFillBackground(true);
    setFrameShape(QFrame::Box);
    setMargin(4);
    QPalette p = palette();
    p.setColor(QPalette::Window, QColor(0xfd, 0xe8, 0xe8));  // a pale red: refused
    p.setColor(QPalette::WindowText, QColor(0x80, 0x10, 0x10));
    setPalette(p);
    hide();
    hide_.setSingleShot(true);
    hide_.setInterval(kShownMs);
    connect(&hide_, &QTimer::timeout, this, &QWidget::hide);
    connect(qApp, &QApplication::focusChanged, this, [this](QWidget*, QWidget* now) {
        // The focus went on to another field: the note about the last one goes.
        if (isVisible() && now && field_ && now != field_ && !field_->isAncestorOf(now)) hide();
    });
}

bool RefusalNote::say(const QString& message)
{
    QWidget* field = QApplication::focusWidget();
    cell_ = QRect();
    // A spin box's text field stands for the spin box; a cell's editor (Balls' coordinates) for its
    // cell in the list, which keeps the focus once the editor closes.
    for (QWidget* w = field; w; w = w->parentWidget())
        if (qobject_cast<QAbstractSpinBox*>(w)) field = w;
    for (QWidget* w = field; w; w = w->parentWidget())
        if (auto* view = qobject_cast<QAbstractItemView*>(w)) {
            field = view;
            const QRect cell = view->visualRect(view->currentIndex());
            if (cell.isValid()) cell_ = QRect(view->viewport()->mapTo(view, cell.topLeft()), cell.size());
            break;
        }
    bool inDock = false;
    for (QWidget* w = field; w && w != window_; w = w->parentWidget()) {
        if (w->property("saysRefusals").toBool()) return false;
        if (qobject_cast<QDockWidget*>(w)) inDock = true;
    }
    if (!field || !inDock || field->window() != window_) {
        hide();
        return false;
    }
    if (field_) field_->removeEventFilter(this);
    field_ = field;
    field_->installEventFilter(this);
    setText(message);
    place();
    show();
    raise();
    hide_.start();
    return true;
}

bool RefusalNote::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == field_ && (event->type() == QEvent::Move || event->type() == QEvent::Resize)) place();
    if (watched == field_ && event->type() == QEvent::Hide) hide();
    return QLabel::eventFilter(watched, event);
}

void RefusalNote::place()
{
    if (!field_) return;
    // Under the field (its cell), as wide as it at least, inside the window.
    const QRect anchor = cell_.isValid() ? cell_ : field_->rect();
    const QPoint at = field_->mapTo(window_, anchor.bottomLeft() + QPoint(0, 3));
    const int width = std::clamp(std::max(anchor.width(), 260), 120, std::max(120, window_->width() - 8));
    setFixedWidth(width);
    const int height = heightForWidth(width);
    setFixedHeight(height > 0 ? height : sizeHint().height());
    const int x = std::clamp(at.x(), 4, std::max(4, window_->width() - width - 4));
    int y = at.y();
    if (y + this->height() > window_->height() - 4) y = field_->mapTo(window_, anchor.topLeft()).y() - this->height() - 2;
    move(x, std::max(0, y));
}

}  // namespace cuelab
