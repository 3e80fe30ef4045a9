#include "OutcomeMap.h"

#include "i18n/UiNumbers.h"

#include "i18n/DisplayNames.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>

#include <cmath>

namespace cuelab {

using analysis::ShotClass;

OutcomeMap::OutcomeMap(QWidget* parent) : QWidget(parent)
{
    setMouseTracking(false);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

QColor OutcomeMap::colourOf(ShotClass c)
{
    switch (c) {
    case ShotClass::GoalMet: return {46, 160, 67};
    case ShotClass::Missed: return {240, 170, 50};
    case ShotClass::NoContact: return {150, 170, 200};
    case ShotClass::Scratch: return {210, 60, 50};
    case ShotClass::Refused: return {70, 70, 70};
    case ShotClass::Unfinished: return {150, 80, 180};
    case ShotClass::Outside: return {0, 0, 0, 0};
    }
    return Qt::transparent;
}

void OutcomeMap::reset(const analysis::Variation& x, const analysis::Variation& y, bool disk)
{
    x_ = x;
    y_ = y;
    disk_ = disk;
    nx_ = x.range.count;
    ny_ = y.range.count;
    const auto n = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
    classes_.assign(n, ShotClass::Outside);
    known_.assign(n, false);
    tips_.assign(n, QString());
    counts_.fill(0);
    filled_ = 0;
    stale_ = false;
    update();
}

void OutcomeMap::clear()
{
    x_.reset();
    y_.reset();
    nx_ = ny_ = filled_ = 0;
    classes_.clear();
    known_.clear();
    tips_.clear();
    counts_.fill(0);
    update();
}

void OutcomeMap::addResult(const analysis::ShotResult& shot, const QString& tip)
{
    const auto i = static_cast<std::size_t>(shot.index);
    if (i >= classes_.size()) return;
    const ShotClass c = analysis::classifyShot(shot);
    if (!known_[i]) ++filled_;
    else --counts_[static_cast<std::size_t>(classes_[i])];
    known_[i] = true;
    classes_[i] = c;
    tips_[i] = tip;
    ++counts_[static_cast<std::size_t>(c)];
    update();
}

void OutcomeMap::setCurrent(double x, double y)
{
    current_ = QPointF(x, y);
    update();
}

void OutcomeMap::setStale(bool stale)
{
    stale_ = stale;
    update();
}

std::vector<double> OutcomeMap::valuesOf(int index) const
{
    if (!x_ || index < 0 || index >= nx_ * ny_) return {};
    return {x_->range.value(index % nx_), y_->range.value(index / nx_)};
}

QRectF OutcomeMap::plotRect() const
{
    const int fh = fontMetrics().height();
    const double legendHeight = (fh + 2) * ((analysis::kShotClassCount + 1) / 2) + 6;
    const double left = fh * 2.5, right = 8, top = 6, bottom = fh * 2.5 + legendHeight;
    const double w = std::max(10.0, width() - left - right), h = std::max(10.0, height() - top - bottom);
    const double side = std::min(w, h);  // square cells
    return {left + (w - side) / 2, top, side, side};
}

int OutcomeMap::cellAt(const QPointF& point) const
{
    if (nx_ == 0) return -1;
    const QRectF r = plotRect();
    if (!r.contains(point)) return -1;
    const int ix = std::clamp(static_cast<int>((point.x() - r.left()) / r.width() * nx_), 0, nx_ - 1);
    // y grows upwards on the map.
    const int iy = std::clamp(static_cast<int>((r.bottom() - point.y()) / r.height() * ny_), 0, ny_ - 1);
    return iy * nx_ + ix;
}

QPointF OutcomeMap::cellCentre(int index) const
{
    const QRectF r = plotRect();
    const int ix = index % nx_, iy = index / nx_;
    return {r.left() + (ix + 0.5) * r.width() / nx_, r.bottom() - (iy + 0.5) * r.height() / ny_};
}

void OutcomeMap::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    const QColor text = palette().color(QPalette::WindowText);
    if (nx_ == 0) {
        p.setPen(text);
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, tr("No map yet: choose the axes and press Map."));
        return;
    }
    const QRectF r = plotRect();
    const double cw = r.width() / nx_, ch = r.height() / ny_;
    p.fillRect(r, palette().color(QPalette::Base));
    for (int i = 0; i < nx_ * ny_; ++i) {
        if (!known_[static_cast<std::size_t>(i)]) continue;
        QColor c = colourOf(classes_[static_cast<std::size_t>(i)]);
        if (c.alpha() == 0) continue;
        if (stale_) c.setAlpha(90);
        const QPointF centre = cellCentre(i);
        p.fillRect(QRectF(centre.x() - cw / 2, centre.y() - ch / 2, cw + 0.5, ch + 0.5), c);
    }
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(text, 1));
    p.setBrush(Qt::NoBrush);
    if (disk_) {
        // The miscue limit: the disk of the tip offsets that were simulated.
        p.setPen(QPen(text, 1, Qt::DashLine));
        p.drawEllipse(r.adjusted(cw / 2 - 0.5, ch / 2 - 0.5, -cw / 2 + 0.5, -ch / 2 + 0.5));
        p.setPen(QPen(text, 1));
    }
    p.drawRect(r);

    // Axes: the parameters by name with their units, and the ends of the ranges.
    const int fh = fontMetrics().height();
    const auto label = [](const analysis::Variation& v) { return displayKeyName(v.parameter.key()); };
    const auto number = [](double v) { return uiSignificant(v, 4); };
    p.drawText(QRectF(r.left(), r.bottom() + 2, r.width(), fh), Qt::AlignLeft, number(x_->range.from));
    p.drawText(QRectF(r.left(), r.bottom() + 2, r.width(), fh), Qt::AlignRight, number(x_->range.to));
    p.drawText(QRectF(r.left(), r.bottom() + 2, r.width(), fh), Qt::AlignHCenter, label(*x_));
    p.save();
    p.translate(r.left() - 4, r.bottom());
    p.rotate(-90);
    p.drawText(QRectF(0, -fh, r.height(), fh), Qt::AlignLeft, number(y_->range.from));
    p.drawText(QRectF(0, -fh, r.height(), fh), Qt::AlignRight, number(y_->range.to));
    p.drawText(QRectF(0, -fh, r.height(), fh), Qt::AlignHCenter, label(*y_));
    p.restore();

    if (current_) {
        const double fx = (current_->x() - x_->range.from) / (x_->range.to - x_->range.from);
        const double fy = (current_->y() - y_->range.from) / (y_->range.to - y_->range.from);
        if (std::isfinite(fx) && std::isfinite(fy)) {
            const QPointF c(r.left() + fx * r.width(), r.bottom() - fy * r.height());
            p.setPen(QPen(Qt::white, 3));
            p.drawLine(c - QPointF(6, 0), c + QPointF(6, 0));
            p.drawLine(c - QPointF(0, 6), c + QPointF(0, 6));
            p.setPen(QPen(Qt::black, 1.5));
            p.drawLine(c - QPointF(6, 0), c + QPointF(6, 0));
            p.drawLine(c - QPointF(0, 6), c + QPointF(0, 6));
        }
    }

    // Legend: two columns of swatches with counts.
    const double top = r.bottom() + fh * 1.6;
    const double columnWidth = (width() - 16) / 2.0;
    int slot = 0;
    for (int k = 0; k < analysis::kShotClassCount; ++k) {
        const auto c = static_cast<ShotClass>(k);
        if (c == ShotClass::Outside && !disk_) continue;
        const double x = 8 + (slot % 2) * columnWidth, y = top + (slot / 2) * (fh + 2);
        QColor swatch = colourOf(c);
        p.setPen(QPen(text, 0.5));
        p.setBrush(swatch.alpha() == 0 ? palette().color(QPalette::Base) : swatch);
        p.drawRect(QRectF(x, y + 2, fh - 4, fh - 4));
        p.setPen(text);
        const QString line = QStringLiteral("%1 (%2)").arg(QString::fromUtf8(analysis::toString(c).data()))
                                 .arg(counts_[static_cast<std::size_t>(k)]);
        p.drawText(QRectF(x + fh, y, columnWidth - fh, fh), Qt::AlignLeft | Qt::AlignVCenter,
                   fontMetrics().elidedText(line, Qt::ElideRight, static_cast<int>(columnWidth - fh)));
        ++slot;
    }
}

void OutcomeMap::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) return;
    const int cell = cellAt(event->position());
    if (cell < 0) return;
    const std::vector<double> v = valuesOf(cell);
    emit cellClicked(v[0], v[1], cell);
}

bool OutcomeMap::event(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        const auto* help = static_cast<QHelpEvent*>(event);
        const int cell = cellAt(help->pos());
        if (cell >= 0 && known_[static_cast<std::size_t>(cell)])
            QToolTip::showText(help->globalPos(), tips_[static_cast<std::size_t>(cell)], this);
        else
            QToolTip::hideText();
        return true;
    }
    return QWidget::event(event);
}

}  // namespace cuelab
