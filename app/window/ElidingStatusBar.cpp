#include "ElidingStatusBar.h"

#include <QPainter>
#include <algorithm>
#include <QStyle>
#include <QStyleOption>

namespace cuelab::window {

ElidingStatusBar::ElidingStatusBar(QWidget* parent)
    : QStatusBar(parent)
{
    connect(this, &QStatusBar::messageChanged, this, [this](const QString& message) {
        setToolTip(message.isEmpty() || shownMessage() == message ? QString() : message);
        update();
    });
}

QRect ElidingStatusBar::messageRect() const
{
    // As QStatusBar lays its message out: 6 px from the left, 12 px short of the right (the size
    // grip), and never over a permanent widget (the only children visible while a message shows).
    const bool rtl = layoutDirection() == Qt::RightToLeft;
    int left = 6, right = width() - 12;
    for (const QObject* child : children()) {
        const auto* w = qobject_cast<const QWidget*>(child);
        if (!w || !w->isVisible() || w->isWindow() || w->width() == 0) continue;
        if (rtl) left = std::max(left, w->x() + w->width() + 2);
        else right = std::min(right, w->x() - 2);
    }
    return QRect(left, 0, std::max(0, right - left), height());
}

QString ElidingStatusBar::shownMessage() const
{
    return fontMetrics().elidedText(currentMessage(), Qt::ElideMiddle, messageRect().width());
}

void ElidingStatusBar::paintEvent(QPaintEvent* event)
{
    if (currentMessage().isEmpty()) {
        QStatusBar::paintEvent(event);
        return;
    }
    QPainter p(this);
    QStyleOption opt;
    opt.initFrom(this);
    style()->drawPrimitive(QStyle::PE_PanelStatusBar, &opt, &p, this);
    for (const QObject* child : children()) {
        const auto* w = qobject_cast<const QWidget*>(child);
        if (!w || !w->isVisible() || w->isWindow()) continue;
        QStyleOption item;
        item.rect = w->geometry().adjusted(-2, -1, 2, 1);
        item.palette = palette();
        item.state = QStyle::State_None;
        style()->drawPrimitive(QStyle::PE_FrameStatusBarItem, &item, &p, w);
    }
    p.setPen(palette().windowText().color());
    p.drawText(messageRect(), Qt::AlignLeading | Qt::AlignVCenter | Qt::TextSingleLine, shownMessage());
}

}  // namespace cuelab::window
