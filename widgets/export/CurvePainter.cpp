#include "CurvePainter.h"

#include "i18n/UiNumbers.h"

#include "view/BallAppearance.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace cuelab {

namespace {

// The context lupdate gives tr() calls in functions of namespace cuelab (resources/translations).
QString tr(const char* text) { return QCoreApplication::translate("cuelab", text); }

QColor printColour(TableKind kind, const std::string& id)
{
    const QVector3D c = ballLook(kind, id).colour;
    auto g = [](float v) { return static_cast<float>(std::pow(std::clamp(static_cast<double>(v), 0.0, 1.0), 1.0 / 2.2)); };
    QColor q = QColor::fromRgbF(g(c.x()), g(c.y()), g(c.z()));
    if (q.lightnessF() > 0.6) q = q.darker(q.saturationF() < 0.2 ? 260 : 150);
    return q;
}

// A "nice" tick step: 1, 2 or 5 times a power of ten, giving about `count` ticks over `span`.
double niceStep(double span, int count)
{
    if (!(span > 0.0)) return 1.0;
    const double raw = span / count;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= raw) return m * p;
    return 10.0 * p;
}

QFont font(double px, bool bold = false)
{
    QFont f(QStringLiteral("DejaVu Sans"));
    f.setPixelSize(std::max(1, static_cast<int>(std::lround(px))));
    f.setBold(bold);
    return f;
}

}  // namespace

std::vector<ChartLine> chartLines(const SimulationResult& result, plots::Quantity q)
{
    std::vector<ChartLine> lines;
    plots::SamplingOptions options;
    options.samplesPerPiece = 16;
    options.maxStep = std::max(result.endTime, 1e-3) / 400.0;
    for (int b = 0; b < static_cast<int>(result.balls.size()); ++b) {
        ChartLine line;
        line.name = QString::fromStdString(result.balls[b].id);
        line.colour = printColour(result.table.kind, result.balls[b].id);
        line.curve = plots::ballCurve(result, b, q, options);
        double top = 0.0;
        for (const plots::Polyline& p : line.curve)
            for (const double v : p.values) top = std::max(top, std::abs(v));
        if (top > 0.0) lines.push_back(std::move(line));  // balls that never move stay off the chart
    }
    if (plots::isEnergy(q) && result.balls.size() > 1)
        lines.push_back({tr("table total"), Qt::black, plots::tableCurve(result, q, options), true});
    return lines;
}

void paintChart(QPainter& p, const QRectF& area, const QString& title, const QString& unit,
                const std::vector<ChartLine>& lines, const SimulationResult& result)
{
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    const double em = std::max(8.0, area.height() / 22.0);
    const QFont small = font(em * 0.8);
    const QFontMetricsF fm(small);
    const QRectF plot = area.adjusted(fm.horizontalAdvance(QStringLiteral("-0.000")) + em, 1.8 * em, -em * 0.5, -2.6 * em);

    double t1 = std::max(result.endTime, 1e-3);
    double v0 = 0.0;
    double v1 = 0.0;
    for (const ChartLine& l : lines)
        for (const plots::Polyline& poly : l.curve)
            for (const double v : poly.values) {
                v0 = std::min(v0, v);
                v1 = std::max(v1, v);
            }
    if (!(v1 > v0)) v1 = v0 + 1.0;
    v1 += 0.05 * (v1 - v0);
    auto X = [&](double t) { return plot.left() + t / t1 * plot.width(); };
    auto Y = [&](double v) { return plot.bottom() - (v - v0) / (v1 - v0) * plot.height(); };

    p.setFont(font(em, true));
    p.setPen(Qt::black);
    p.drawText(QRectF(area.left(), area.top(), area.width(), 1.5 * em), Qt::AlignLeft | Qt::AlignVCenter,
               title + QStringLiteral(" (") + unit + QLatin1Char(')'));

    // Grid and ticks.
    p.setFont(small);
    p.setPen(QPen(QColor(225, 225, 225), 0.6));
    const double ts = niceStep(t1, 8);
    const double vs = niceStep(v1 - v0, 5);
    for (double t = 0.0; t <= t1 + 1e-12; t += ts) p.drawLine(QPointF(X(t), plot.top()), QPointF(X(t), plot.bottom()));
    for (double v = std::ceil(v0 / vs) * vs; v <= v1; v += vs) p.drawLine(QPointF(plot.left(), Y(v)), QPointF(plot.right(), Y(v)));
    p.setPen(Qt::black);
    for (double t = 0.0; t <= t1 + 1e-12; t += ts)
        p.drawText(QRectF(X(t) - 3 * em, plot.bottom() + 0.2 * em, 6 * em, em), Qt::AlignHCenter | Qt::AlignTop, uiSignificant(t, 4));
    for (double v = std::ceil(v0 / vs) * vs; v <= v1; v += vs)
        p.drawText(QRectF(area.left(), Y(v) - em / 2, plot.left() - area.left() - 0.3 * em, em), Qt::AlignRight | Qt::AlignVCenter,
                   uiSignificant(std::abs(v) < vs * 1e-9 ? 0.0 : v, 4));
    p.drawText(QRectF(plot.left(), plot.bottom() + 1.1 * em, plot.width(), em), Qt::AlignHCenter, tr("time (s)"));
    p.setPen(QPen(Qt::black, 0.8));
    p.setBrush(Qt::NoBrush);
    p.drawRect(plot);

    // Event ticks along the bottom (collisions and pocketings).
    p.setPen(QPen(QColor(150, 150, 150), 0.8));
    for (const Event& e : result.events)
        if (isCollision(e.kind) || e.kind == EventKind::BallPocket)
            p.drawLine(QPointF(X(e.time), plot.bottom()), QPointF(X(e.time), plot.bottom() - 0.4 * em));

    // The lines, clipped to the plot.
    p.setClipRect(plot);
    for (const ChartLine& l : lines) {
        QPen pen(l.colour, std::max(0.8, em / 8), l.tableTotal ? Qt::DashLine : Qt::SolidLine);
        p.setPen(pen);
        for (const plots::Polyline& poly : l.curve) {
            QPolygonF points;
            for (std::size_t i = 0; i < poly.times.size(); ++i) points << QPointF(X(poly.times[i]), Y(poly.values[i]));
            p.drawPolyline(points);
        }
    }
    p.setClipping(false);

    // Legend along the top right.
    double x = plot.right();
    for (auto it = lines.rbegin(); it != lines.rend(); ++it) {
        const double w = fm.horizontalAdvance(it->name) + 2.2 * em;
        x -= w;
        if (x < plot.left() + 10 * em) break;
        p.setPen(QPen(it->colour, std::max(1.0, em / 6)));
        p.drawLine(QPointF(x, area.top() + 0.75 * em), QPointF(x + 1.2 * em, area.top() + 0.75 * em));
        p.setPen(Qt::black);
        p.drawText(QRectF(x + 1.4 * em, area.top(), w, 1.5 * em), Qt::AlignLeft | Qt::AlignVCenter, it->name);
    }
    p.restore();
}

}  // namespace cuelab
