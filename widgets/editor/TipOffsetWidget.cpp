#include "TipOffsetWidget.h"

#include <QMouseEvent>
#include <QPainter>
#include <QRadialGradient>

#include <cmath>

namespace cuelab {

TipOffsetWidget::TipOffsetWidget(QWidget* parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
    setMaximumSize(180, 180);
    setCursor(Qt::CrossCursor);
    setToolTip(tr("Cue tip offset on the ball's face, as the player sees it. Click or drag to place "
                  "the tip; the dashed circle is the miscue limit (half the radius)."));
}

void TipOffsetWidget::setOffset(const QPointF& sideHeight)
{
    if (sideHeight == offset_) return;
    offset_ = sideHeight;
    update();
}

QRectF TipOffsetWidget::ballRect() const
{
    const double side = std::min(width(), height()) - 8.0;
    return {(width() - side) / 2.0, (height() - side) / 2.0, side, side};
}

QPointF TipOffsetWidget::offsetAt(const QPointF& widgetPos) const
{
    const QRectF ball = ballRect();
    const double radius = ball.width() / 2.0;
    double side = (widgetPos.x() - ball.center().x()) / radius;
    double height = (ball.center().y() - widgetPos.y()) / radius;  // widget y grows downwards
    const double length = std::hypot(side, height);
    if (length > kMaxOffset) {
        side *= kMaxOffset / length;
        height *= kMaxOffset / length;
    }
    // Two decimals of the radius (0.3 mm on a pool ball) are finer than any cue tip is placed.
    return {std::round(side * 100.0) / 100.0, std::round(height * 100.0) / 100.0};
}

void TipOffsetWidget::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF ball = ballRect();
    const double radius = ball.width() / 2.0;
    const QPointF c = ball.center();

    QRadialGradient shade(c - QPointF(radius * 0.35, radius * 0.35), radius * 1.4);
    shade.setColorAt(0.0, QColor(255, 255, 252));
    shade.setColorAt(1.0, QColor(206, 204, 196));
    p.setPen(QPen(palette().color(QPalette::Mid), 1.0));
    p.setBrush(shade);
    p.drawEllipse(ball);

    p.setPen(QPen(QColor(0, 0, 0, 60), 1.0));
    p.drawLine(QPointF(ball.left(), c.y()), QPointF(ball.right(), c.y()));
    p.drawLine(QPointF(c.x(), ball.top()), QPointF(c.x(), ball.bottom()));
    p.setPen(QPen(QColor(150, 60, 50, 140), 1.0, Qt::DashLine));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(c, radius * kMiscueLimit, radius * kMiscueLimit);

    const QPointF tip(c.x() + offset_.x() * radius, c.y() - offset_.y() * radius);
    const double tipRadius = std::max(4.0, radius * 0.12);
    p.setPen(QPen(QColor(20, 60, 120), 1.5));
    p.setBrush(QColor(60, 120, 200, 190));
    p.drawEllipse(tip, tipRadius, tipRadius);
}

void TipOffsetWidget::mousePressEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) return;
    offset_ = offsetAt(event->position());
    update();
    emit offsetEdited(offset_);
}

void TipOffsetWidget::mouseMoveEvent(QMouseEvent* event)
{
    if (!(event->buttons() & Qt::LeftButton)) return;
    const QPointF o = offsetAt(event->position());
    if (o == offset_) return;
    offset_ = o;
    update();
    emit offsetEdited(offset_);
}

void TipOffsetWidget::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton) emit editingFinished();
}

}  // namespace cuelab
