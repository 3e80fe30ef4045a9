#include "OverlayLabels.h"

#include "OverlayLines.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <optional>
#include <vector>

namespace cuelab {

namespace {

std::optional<QPointF> toScreen(const LabelFrame& frame, const QVector3D& world)
{
    const QVector4D clip = frame.viewProjection * QVector4D(world, 1.0f);
    if (clip.w() <= 1e-6f) return std::nullopt;
    const double x = clip.x() / clip.w(), y = clip.y() / clip.w();
    if (x < -1.2 || x > 1.2 || y < -1.2 || y > 1.2) return std::nullopt;
    return QPointF((x + 1.0) / 2.0 * frame.logicalSize.width(), (1.0 - y) / 2.0 * frame.logicalSize.height());
}

// Text as filled outlines, centred in `box`. Qt's glyph-cache text is unreliable on a core-profile
// GL paint device (garbled glyphs on Mesa); outlines draw the same on every device.
void text(QPainter& painter, const QRectF& box, const QString& string, const QColor& ink)
{
    const QFontMetricsF metrics(painter.font());
    const double width = metrics.horizontalAdvance(string);
    const QPointF baseline(box.center().x() - width / 2.0, box.center().y() + (metrics.ascent() - metrics.descent()) / 2.0);
    QPainterPath path;
    path.addText(baseline, painter.font(), string);
    painter.fillPath(path, ink);
}

void tag(QPainter& painter, const QRectF& box, const QString& string, const QColor& ink, const QColor& fill)
{
    QPainterPath path;
    path.addRoundedRect(box, 3.0, 3.0);
    painter.fillPath(path, fill);
    text(painter, box, string, ink);
}

void paintEventTimes(QPainter& painter, const ViewScene& scene, const LabelFrame& frame)
{
    const SimulationResult& r = *scene.result;
    const QFontMetricsF metrics(painter.font());
    std::vector<QRectF> taken;
    // The highlighted event first, so that it always gets its label.
    std::vector<int> order;
    if (frame.highlightedEvent >= 0 && static_cast<std::size_t>(frame.highlightedEvent) < r.events.size())
        order.push_back(frame.highlightedEvent);
    for (std::size_t e = 0; e < r.events.size(); ++e)
        if (static_cast<int>(e) != frame.highlightedEvent) order.push_back(static_cast<int>(e));
    for (int e : order) {
        const Event& ev = r.events[static_cast<std::size_t>(e)];
        if (!isCollision(ev.kind) && ev.kind != EventKind::BallPocket) continue;
        const Vec2 p = ev.kind == EventKind::BallPocket ? ev.before[0].position : ev.contactPoint;
        const double radius = ev.balls[0] >= 0 ? r.balls[static_cast<std::size_t>(ev.balls[0])].radius : r.table.ballRadius;
        const std::optional<QPointF> at = toScreen(frame, QVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                                                    static_cast<float>(radius)));
        if (!at) continue;
        const QString label = QStringLiteral("%1 s").arg(ev.time, 0, 'f', 3);
        const QSizeF size = metrics.size(Qt::TextSingleLine, label) + QSizeF(8.0, 2.0);
        const QRectF box(*at + QPointF(9.0, -size.height() - 6.0), size);
        bool overlaps = false;
        for (const QRectF& t : taken) overlaps = overlaps || t.intersects(box);
        const bool highlighted = e == frame.highlightedEvent;
        if (overlaps && !highlighted) continue;
        taken.push_back(box);
        const bool future = ev.time > frame.time;
        const QColor ink = highlighted ? QColor(20, 20, 0) : (future ? QColor(220, 220, 220, 150) : QColor(255, 255, 255));
        const QColor fill = highlighted ? QColor(255, 235, 60, 230) : QColor(0, 0, 0, future ? 90 : 160);
        tag(painter, box, label, ink, fill);
    }
}

// A bar exactly as long on screen as a velocity arrow drawn at the middle of the table, for the
// largest round speed whose bar fits in 240 pixels.
void paintVelocityLegend(QPainter& painter, const ViewScene& scene, const LabelFrame& frame)
{
    const Table& t = scene.result->table;
    const auto z = static_cast<float>(t.ballRadius);
    const QVector3D centre(static_cast<float>(t.length / 2), static_cast<float>(t.width / 2), z);
    const std::optional<QPointF> a = toScreen(frame, centre);
    const std::optional<QPointF> b = toScreen(frame, centre + QVector3D(static_cast<float>(kVelocityArrowScale), 0, 0));
    const std::optional<QPointF> c = toScreen(frame, centre + QVector3D(0, static_cast<float>(kVelocityArrowScale), 0));
    if (!a || !b || !c) return;
    const double perMetrePerSecond = std::max(QLineF(*a, *b).length(), QLineF(*a, *c).length());  // pixels
    double speed = 1.0;  // m/s
    for (double candidate : {5.0, 2.0, 1.0, 0.5, 0.2, 0.1, 0.05, 0.02}) {
        speed = candidate;
        if (candidate * perMetrePerSecond <= 240.0) break;
    }
    const double length = speed * perMetrePerSecond;
    if (length < 4.0) return;
    const QFontMetricsF metrics(painter.font());
    const QString label = QStringLiteral("%1 m/s").arg(speed);
    const double h = metrics.height();
    const QRectF box(10.0, frame.logicalSize.height() - 2.0 * h - 14.0, length + metrics.horizontalAdvance(label) + 28.0,
                     h + 12.0);
    QPainterPath path;
    path.addRoundedRect(box, 4.0, 4.0);
    painter.fillPath(path, QColor(0, 0, 0, 150));
    const double y = box.center().y();
    const double x0 = box.left() + 8.0, x1 = x0 + length;
    painter.setPen(QPen(QColor(255, 237, 77), 3.0));
    painter.drawLine(QPointF(x0, y), QPointF(x1, y));
    painter.drawLine(QPointF(x1, y), QPointF(x1 - 7.0, y - 4.0));
    painter.drawLine(QPointF(x1, y), QPointF(x1 - 7.0, y + 4.0));
    text(painter, QRectF(x1 + 8.0, box.top(), metrics.horizontalAdvance(label) + 4.0, box.height()), label, Qt::white);
}

}  // namespace

void paintOverlayLabels(QPainter& painter, const ViewScene& scene, const LabelFrame& frame)
{
    if (!scene.result) return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    QFont font = painter.font();
    font.setPixelSize(12);
    painter.setFont(font);
    if (frame.overlays.test(static_cast<std::size_t>(Overlay::EventMarkers))) paintEventTimes(painter, scene, frame);
    if (frame.overlays.test(static_cast<std::size_t>(Overlay::Velocities))) paintVelocityLegend(painter, scene, frame);
    painter.restore();
}

}  // namespace cuelab
