#include "PlotsChartView.h"

#include <QLegendMarker>
#include <QLineSeries>
#include <QMouseEvent>
#include <QScatterSeries>
#include <QToolTip>
#include <QValueAxis>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace cuelab {

namespace {

constexpr double kMarkerPickRadius = 7.0;  // px
constexpr int kTimeTicks = 8, kValueTicks = 5;  // about as many ticks on each axis

// Ticks at 1, 2 or 5 times a power of ten, about `count` of them over [lo, hi] (the axis' range by
// default). The interval must suit a new range before the axis takes it: the axis lays out its ticks
// at once, and the last range's interval over a range a thousand times longer is a thousand times as
// many tick items (a second of layout: a shot of a millisecond followed by one of seconds).
void niceTicks(QValueAxis* axis, int count, double lo, double hi)
{
    const double span = hi - lo;
    if (!(span > 0.0)) return;
    const double raw = span / count;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    double step = 10.0 * p;
    for (const double m : {1.0, 2.0, 5.0})
        if (m * p >= raw) {
            step = m * p;
            break;
        }
    axis->setTickAnchor(0.0);
    axis->setTickInterval(step);
}

void niceTicks(QValueAxis* axis, int count) { niceTicks(axis, count, axis->min(), axis->max()); }

// A range and its ticks together, the ticks first.
void setRangeWithTicks(QValueAxis* axis, int count, double lo, double hi)
{
    if (hi - lo > axis->max() - axis->min()) niceTicks(axis, count, lo, hi);  // (a narrower one: after)
    axis->setRange(lo, hi);
}

}  // namespace

PlotsChartView::PlotsChartView(QWidget* parent) : QChartView(parent)
{
    setRenderHint(QPainter::Antialiasing);
    setMouseTracking(true);
    QChart* c = chart();
    c->setLocalizeNumbers(true);  // axis labels in the interface's language ("0,56")
    c->legend()->setAlignment(Qt::AlignRight);
    c->setMargins(QMargins(4, 4, 4, 4));
    timeAxis_ = new QValueAxis(c);
    timeAxis_->setTitleText(tr("time (s)"));
    timeAxis_->setLabelFormat(QStringLiteral("%.4g"));
    timeAxis_->setTickType(QValueAxis::TicksDynamic);
    valueAxis_ = new QValueAxis(c);
    valueAxis_->setLabelFormat(QStringLiteral("%.4g"));
    valueAxis_->setTickType(QValueAxis::TicksDynamic);
    c->addAxis(timeAxis_, Qt::AlignBottom);
    c->addAxis(valueAxis_, Qt::AlignLeft);

    markerSeries_ = new QScatterSeries(c);
    markerSeries_->setName(tr("events"));
    markerSeries_->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
    markerSeries_->setMarkerSize(7.0);
    markerSeries_->setColor(QColor(40, 40, 40));
    markerSeries_->setBorderColor(Qt::white);
    highlightSeries_ = new QScatterSeries(c);
    highlightSeries_->setName(tr("selected event"));
    highlightSeries_->setMarkerSize(13.0);
    highlightSeries_->setColor(QColor(255, 160, 0, 170));
    highlightSeries_->setBorderColor(QColor(200, 90, 0));
    cursorLine_ = new QLineSeries(c);
    cursorLine_->setName(tr("cursor"));
    cursorLine_->setPen(QPen(QColor(200, 30, 30), 1.5));
    for (QXYSeries* s : std::initializer_list<QXYSeries*>{highlightSeries_, markerSeries_, cursorLine_}) {
        c->addSeries(s);
        s->attachAxis(timeAxis_);
        s->attachAxis(valueAxis_);
    }
    for (QXYSeries* s : std::initializer_list<QXYSeries*>{highlightSeries_, cursorLine_})
        for (QLegendMarker* m : c->legend()->markers(s)) m->setVisible(false);

    connect(markerSeries_, &QScatterSeries::hovered, this, [this](const QPointF& point, bool state) {
        if (!state) {
            QToolTip::hideText();
            return;
        }
        const int event = markerAt(positionOf(point.x(), point.y()));
        for (const Marker& m : markers_)
            if (m.event == event) QToolTip::showText(QCursor::pos(), m.name, this);
    });
    connect(valueAxis_, &QValueAxis::rangeChanged, this, [this] {
        niceTicks(valueAxis_, kValueTicks);
        updateCursorLine();
    });
    connect(timeAxis_, &QValueAxis::rangeChanged, this, [this] { niceTicks(timeAxis_, kTimeTicks); });
    setToolTip(tr("Drag: move the time cursor. Wheel: zoom the time axis (Ctrl: the value axis). "
                  "Shift-drag or middle-drag: pan. Double-click: show everything. Click a marker to select its event."));
}

void PlotsChartView::setFullRange(double t0, double t1, double v0, double v1)
{
    if (!(t1 > t0)) t1 = t0 + 1.0;
    if (!(v1 > v0)) {
        v0 -= 0.5;
        v1 += 0.5;
    }
    const double pad = 0.05 * (v1 - v0);
    fullT0_ = t0;
    fullT1_ = t1;
    fullV0_ = v0 < 0 ? v0 - pad : std::min(0.0, v0);
    fullV1_ = v1 + pad;
    resetZoom();
}

void PlotsChartView::resetZoom()
{
    setRangeWithTicks(timeAxis_, kTimeTicks, fullT0_, fullT1_);
    setRangeWithTicks(valueAxis_, kValueTicks, fullV0_, fullV1_);
    updateCursorLine();
}

void PlotsChartView::setCursorTime(double t)
{
    cursor_ = t;
    updateCursorLine();
}

void PlotsChartView::updateCursorLine()
{
    cursorLine_->replace(QList<QPointF>{QPointF(cursor_, valueAxis_->min()), QPointF(cursor_, valueAxis_->max())});
}

void PlotsChartView::setMarkers(std::vector<Marker> markers)
{
    markers_ = std::move(markers);
    QList<QPointF> points;
    for (const Marker& m : markers_) points << QPointF(m.time, m.value);
    markerSeries_->replace(points);
    highlightSeries_->clear();
}

void PlotsChartView::setHighlightedEvent(int event)
{
    QList<QPointF> points;
    for (const Marker& m : markers_)
        if (m.event == event) points << QPointF(m.time, m.value);
    highlightSeries_->replace(points);
}

QPointF PlotsChartView::positionOf(double t, double v) const
{
    return mapFromScene(chart()->mapToScene(chart()->mapToPosition(QPointF(t, v), cursorLine_)));
}

double PlotsChartView::timeAt(const QPointF& widgetPos) const
{
    return chart()->mapToValue(chart()->mapFromScene(mapToScene(widgetPos.toPoint())), cursorLine_).x();
}

int PlotsChartView::markerAt(const QPointF& widgetPos) const
{
    int best = -1;
    double bestDistance = kMarkerPickRadius;
    for (const Marker& m : markers_) {
        const QPointF p = positionOf(m.time, m.value);
        const double d = std::hypot(p.x() - widgetPos.x(), p.y() - widgetPos.y());
        if (d <= bestDistance) {
            bestDistance = d;
            best = m.event;
        }
    }
    return best;
}

void PlotsChartView::mousePressEvent(QMouseEvent* event)
{
    lastPos_ = event->position();
    if (event->button() == Qt::MiddleButton ||
        (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier))) {
        drag_ = Drag::Pan;
        setCursor(Qt::ClosedHandCursor);
        return;
    }
    if (event->button() != Qt::LeftButton) return;
    const int marker = markerAt(event->position());
    if (marker >= 0) {
        emit markerClicked(marker);
        return;
    }
    if (!chart()->plotArea().contains(chart()->mapFromScene(mapToScene(event->position().toPoint())))) return;
    drag_ = Drag::Cursor;
    const double t = std::clamp(timeAt(event->position()), fullT0_, fullT1_);
    setCursorTime(t);
    emit cursorDragged(t);
}

void PlotsChartView::mouseMoveEvent(QMouseEvent* event)
{
    const QPointF pos = event->position();
    if (drag_ == Drag::Cursor) {
        const double t = std::clamp(timeAt(pos), fullT0_, fullT1_);
        setCursorTime(t);
        emit cursorDragged(t);
    } else if (drag_ == Drag::Pan) {
        const QRectF area = chart()->plotArea();
        const double dt = -(pos.x() - lastPos_.x()) / area.width() * (timeAxis_->max() - timeAxis_->min());
        const double dv = (pos.y() - lastPos_.y()) / area.height() * (valueAxis_->max() - valueAxis_->min());
        timeAxis_->setRange(timeAxis_->min() + dt, timeAxis_->max() + dt);
        valueAxis_->setRange(valueAxis_->min() + dv, valueAxis_->max() + dv);
    } else {
        // Near the cursor line the pointer says that it can be dragged.
        const double x = positionOf(cursor_, valueAxis_->min()).x();
        setCursor(std::abs(pos.x() - x) < 5 ? Qt::SizeHorCursor : Qt::ArrowCursor);
    }
    lastPos_ = pos;
}

void PlotsChartView::mouseReleaseEvent(QMouseEvent*)
{
    drag_ = Drag::None;
    setCursor(Qt::ArrowCursor);
}

void PlotsChartView::mouseDoubleClickEvent(QMouseEvent*) { resetZoom(); }

void PlotsChartView::wheelEvent(QWheelEvent* event)
{
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0.0) return;
    const double factor = std::pow(0.8, steps);
    const QPointF value = chart()->mapToValue(chart()->mapFromScene(mapToScene(event->position().toPoint())), cursorLine_);
    if (event->modifiers() & Qt::ControlModifier) {
        const double v = value.y();
        valueAxis_->setRange(v - (v - valueAxis_->min()) * factor, v + (valueAxis_->max() - v) * factor);
    } else {
        const double t = value.x();
        double t0 = t - (t - timeAxis_->min()) * factor;
        double t1 = t + (timeAxis_->max() - t) * factor;
        if (t1 - t0 > fullT1_ - fullT0_) {
            t0 = fullT0_;
            t1 = fullT1_;
        }
        timeAxis_->setRange(t0, t1);
    }
    event->accept();
}

void PlotsChartView::resizeEvent(QResizeEvent* event)
{
    QChartView::resizeEvent(event);
    updateCursorLine();
}

}  // namespace cuelab
