#include "OddsMap.h"

#include "i18n/UiNumbers.h"

#include "Tolerance.h"

#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <array>
#include <cmath>

namespace cuelab {

OddsMap::OddsMap(QWidget* parent) : QWidget(parent)
{
    setMouseTracking(true);  // the readout follows the mouse
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

QColor OddsMap::colourOf(double probability)
{
    // Five stops of matplotlib's viridis (van der Walt and Smith 2015): even steps of lightness, and
    // readable by people with the common colour-vision deficiencies.
    static constexpr std::array<std::array<int, 3>, 5> stops{
        {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}}};
    const double t = std::clamp(probability, 0.0, 1.0) * 4.0;
    const auto i = static_cast<std::size_t>(std::min(3.0, std::floor(t)));
    const double f = t - static_cast<double>(i);
    const auto mix = [&](std::size_t c) {
        return static_cast<int>(std::lround(stops[i][c] + f * (stops[i + 1][c] - stops[i][c])));
    };
    return {mix(0), mix(1), mix(2)};
}

void OddsMap::reset(const analysis::Variation& x, const analysis::Variation& y)
{
    x_ = x;
    y_ = y;
    nx_ = x.range.count;
    ny_ = y.range.count;
    const auto n = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
    odds_.assign(n, std::nullopt);
    known_.assign(n, 0);
    filled_ = 0;
    best_ = hovered_ = -1;
    readout_.clear();
    update();
}

void OddsMap::clear()
{
    x_.reset();
    y_.reset();
    nx_ = ny_ = filled_ = 0;
    best_ = hovered_ = -1;
    odds_.clear();
    known_.clear();
    readout_.clear();
    current_.reset();
    update();
}

void OddsMap::setCell(long long index, const std::optional<analysis::OddsResult>& odds)
{
    if (index < 0 || index >= static_cast<long long>(odds_.size())) return;
    const auto i = static_cast<std::size_t>(index);
    if (!known_[i]) ++filled_;
    known_[i] = 1;
    odds_[i] = odds;
    // The best cell: the highest probability; among equals the first in grid order, so that the
    // mark does not depend on the order in which cells arrive.
    if (odds && odds->samples > 0) {
        const auto& b = best_ >= 0 ? odds_[static_cast<std::size_t>(best_)] : std::nullopt;
        const double p = odds->probability();
        if (!b || p > b->probability() || (p == b->probability() && index < best_)) best_ = static_cast<int>(index);
    }
    if (hovered_ == static_cast<int>(index)) readout_ = readout(hovered_);
    update();
}

void OddsMap::setCurrent(double x, double y)
{
    current_ = QPointF(x, y);
    update();
}

std::optional<analysis::OddsResult> OddsMap::oddsOf(int index) const
{
    if (index < 0 || index >= static_cast<int>(odds_.size())) return std::nullopt;
    return odds_[static_cast<std::size_t>(index)];
}

std::vector<double> OddsMap::valuesOf(int index) const
{
    if (!x_ || !y_ || index < 0) return {};
    return {x_->range.value(index % nx_), y_->range.value(index / nx_)};
}

QRectF OddsMap::plotRect() const
{
    const int fh = fontMetrics().height();
    const double left = fh + 8, right = fh * 3.5 + 14, top = 6, bottom = fh * 3 + 10;
    const double w = std::max(10.0, width() - left - right), h = std::max(10.0, height() - top - bottom);
    const double side = std::min(w, h);
    return {left + (w - side) / 2, top, side, side};
}

QRectF OddsMap::scaleRect() const
{
    const QRectF r = plotRect();
    return {r.right() + 10, r.top(), 12, r.height()};
}

int OddsMap::cellAt(const QPointF& point) const
{
    if (nx_ == 0) return -1;
    const QRectF r = plotRect();
    if (!r.contains(point)) return -1;
    const int ix = std::clamp(static_cast<int>((point.x() - r.left()) / r.width() * nx_), 0, nx_ - 1);
    const int iy = std::clamp(static_cast<int>((r.bottom() - point.y()) / r.height() * ny_), 0, ny_ - 1);
    return iy * nx_ + ix;
}

QPointF OddsMap::cellCentre(int index) const
{
    const QRectF r = plotRect();
    const int ix = index % nx_, iy = index / nx_;
    return {r.left() + (ix + 0.5) * r.width() / nx_, r.bottom() - (iy + 0.5) * r.height() / ny_};
}

QString OddsMap::readout(int index) const
{
    if (!x_ || !y_ || index < 0 || index >= static_cast<int>(odds_.size())) return {};
    const std::vector<double> v = valuesOf(index);
    const auto value = [](const analysis::Variation& var, double number) {
        return QStringLiteral("%1 %2 %3")
            .arg(QString::fromStdString(var.parameter.key()), QString::number(number, 'g', 5),
                 QString::fromStdString(analysis::unitOf(var.parameter.key())).trimmed())
            .trimmed();
    };
    const QString where = value(*x_, v[0]) + QStringLiteral(", ") + value(*y_, v[1]) + QStringLiteral(": ");
    if (!known_[static_cast<std::size_t>(index)]) return where + tr("not simulated yet");
    const auto& odds = odds_[static_cast<std::size_t>(index)];
    if (!odds) return where + tr("illegal setup");
    const analysis::Interval ci = odds->ci95();
    return where + tr("%1 % (%2–%3 %), %4 of %5 strikes")
                       .arg(std::lround(odds->probability() * 100.0))
                       .arg(std::lround(ci.low * 100.0))
                       .arg(std::lround(ci.high * 100.0))
                       .arg(odds->successes)
                       .arg(odds->samples);
}

void OddsMap::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    const QColor text = palette().color(QPalette::WindowText);
    if (nx_ == 0) {
        p.setPen(text);
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, tr("No map of odds yet: choose the axes and press Map odds."));
        return;
    }
    const QRectF r = plotRect();
    const double cw = r.width() / nx_, ch = r.height() / ny_;
    p.fillRect(r, palette().color(QPalette::Base));
    for (int i = 0; i < nx_ * ny_; ++i) {
        if (!known_[static_cast<std::size_t>(i)]) continue;
        const auto& odds = odds_[static_cast<std::size_t>(i)];
        const QColor c = odds ? colourOf(odds->probability()) : QColor(70, 70, 70);
        const QPointF centre = cellCentre(i);
        p.fillRect(QRectF(centre.x() - cw / 2, centre.y() - ch / 2, cw + 0.5, ch + 0.5), c);
    }
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(text, 1));
    p.setBrush(Qt::NoBrush);
    p.drawRect(r);

    // Axes.
    const int fh = fontMetrics().height();
    const auto label = [](const analysis::Variation& v) {
        const QString unit = QString::fromStdString(analysis::unitOf(v.parameter.key())).trimmed();
        return QString::fromStdString(v.parameter.key()) + (unit.isEmpty() ? QString() : QStringLiteral(" [%1]").arg(unit));
    };
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

    // The colour scale, 0 % at the bottom.
    const QRectF s = scaleRect();
    QLinearGradient gradient(s.bottomLeft(), s.topLeft());
    for (int k = 0; k <= 8; ++k) gradient.setColorAt(k / 8.0, colourOf(k / 8.0));
    p.fillRect(s, gradient);
    p.drawRect(s);
    for (int k = 0; k <= 4; ++k) {
        const double y = s.bottom() - k / 4.0 * s.height();
        p.drawLine(QPointF(s.right(), y), QPointF(s.right() + 3, y));
        p.drawText(QRectF(s.right() + 5, y - fh / 2.0, fh * 3, fh), Qt::AlignLeft | Qt::AlignVCenter,
                   tr("%1 %").arg(k * 25));
    }

    // The best cell: a ring in the background colour and the text colour, visible on any cell.
    if (best_ >= 0) {
        const QPointF c = cellCentre(best_);
        const double radius = std::max(5.0, std::min(cw, ch) * 0.45);  // inside the cell
        p.setPen(QPen(Qt::white, 3));
        p.drawEllipse(c, radius, radius);
        p.setPen(QPen(Qt::black, 1.5));
        p.drawEllipse(c, radius, radius);
    }
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
    if (hovered_ >= 0) {
        const QPointF c = cellCentre(hovered_);
        p.setPen(QPen(text, 1));
        p.drawRect(QRectF(c.x() - cw / 2, c.y() - ch / 2, cw, ch));
    }

    // The readout: the cell under the mouse, or else the best cell.
    p.setPen(text);
    const QString line = hovered_ >= 0 ? readout_
                         : best_ >= 0  ? tr("Best (ringed): %1").arg(readout(best_))
                                       : QString();
    p.drawText(QRectF(4, r.bottom() + fh + 6, width() - 8, fh * 2 + 2), Qt::AlignLeft | Qt::TextWordWrap, line);
}

void OddsMap::mouseMoveEvent(QMouseEvent* event)
{
    const int cell = cellAt(event->position());
    if (cell != hovered_) {
        hovered_ = cell;
        readout_ = readout(cell);
        update();
    }
}

void OddsMap::leaveEvent(QEvent*)
{
    hovered_ = -1;
    readout_.clear();
    update();
}

void OddsMap::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) return;
    const int cell = cellAt(event->position());
    if (cell >= 0) emit cellClicked(cell);
}

}  // namespace cuelab
