#include "OverlayLabels.h"

#include "OverlayLines.h"

#include <QFontMetricsF>
#include <QImage>
#include <QPainter>
#include <QPainterPath>

#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <utility>
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

enum class TagStyle : std::uint8_t { Past, Future, Highlighted };

// Every label drawn as an image once (raster QPainter: antialiased text and edges on any target,
// including a single-sampled GL paint device) and kept: a GL painter uploads an image as a texture
// once per QImage::cacheKey, so an unchanged label costs one textured quad per frame. Keyed by the
// event time and the style (event tags) or by the bar length and speed (the legend).
struct LabelCache {
    qreal devicePixelRatio = 1.0;
    std::map<std::pair<double, TagStyle>, QImage> tags;
    std::map<std::pair<int, double>, QImage> legends;
    std::vector<QRectF> taken;  // reused every frame
    std::vector<int> order;     // reused every frame
};

LabelCache& labelCache(qreal devicePixelRatio)
{
    static LabelCache cache;
    // Bounded: a new scene brings new times; the cache starts over rather than growing without end.
    constexpr std::size_t kMaxImages = 2048;
    if (cache.devicePixelRatio != devicePixelRatio || cache.tags.size() + cache.legends.size() > kMaxImages) {
        cache.tags.clear();
        cache.legends.clear();
        cache.devicePixelRatio = devicePixelRatio;
    }
    return cache;
}

QFont labelFont()
{
    QFont font;
    font.setPixelSize(12);
    return font;
}

// A transparent image of `logical` size at the device pixel ratio, ready to paint on.
QImage blankImage(QSizeF logical, qreal devicePixelRatio)
{
    QImage image((logical * devicePixelRatio).toSize().expandedTo(QSize(1, 1)), QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(devicePixelRatio);
    image.fill(Qt::transparent);
    return image;
}

const QImage& tagImage(LabelCache& cache, double time, TagStyle style)
{
    const auto key = std::make_pair(time, style);
    auto it = cache.tags.find(key);
    if (it != cache.tags.end()) return it->second;
    const QFont font = labelFont();
    const QFontMetricsF metrics(font);
    const QString label = QStringLiteral("%1 s").arg(time, 0, 'f', 3);
    const QSizeF size = metrics.size(Qt::TextSingleLine, label) + QSizeF(8.0, 2.0);
    QImage image = blankImage(size, cache.devicePixelRatio);
    const QColor ink = style == TagStyle::Highlighted ? QColor(20, 20, 0)
                       : style == TagStyle::Future    ? QColor(220, 220, 220, 150)
                                                      : QColor(255, 255, 255);
    const QColor fill = style == TagStyle::Highlighted ? QColor(255, 235, 60, 230)
                        : style == TagStyle::Future    ? QColor(0, 0, 0, 90)
                                                       : QColor(0, 0, 0, 160);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    QPainterPath path;
    path.addRoundedRect(QRectF(QPointF(0, 0), size), 3.0, 3.0);
    painter.fillPath(path, fill);
    painter.setFont(font);
    painter.setPen(ink);
    painter.drawText(QRectF(QPointF(0, 0), size), Qt::AlignCenter, label);
    painter.end();
    return cache.tags.emplace(key, std::move(image)).first->second;
}

void paintEventTimes(QPainter& painter, const ViewScene& scene, const LabelFrame& frame, LabelCache& cache)
{
    const SimulationResult& r = *scene.result;
    std::vector<QRectF>& taken = cache.taken;
    std::vector<int>& order = cache.order;
    taken.clear();
    order.clear();
    // The highlighted event first, so that it always gets its label.
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
        const bool highlighted = e == frame.highlightedEvent;
        const TagStyle style = highlighted ? TagStyle::Highlighted : (ev.time > frame.time ? TagStyle::Future : TagStyle::Past);
        const QImage& image = tagImage(cache, ev.time, style);
        const QSizeF size = image.deviceIndependentSize();
        const QRectF box(*at + QPointF(9.0, -size.height() - 6.0), size);
        bool overlaps = false;
        for (const QRectF& t : taken) overlaps = overlaps || t.intersects(box);
        if (overlaps && !highlighted) continue;
        taken.push_back(box);
        painter.drawImage(box.topLeft(), image);
    }
}

// The legend's image: a bar `length` pixels long for `speed` (m/s) and its label.
const QImage& legendImage(LabelCache& cache, int length, double speed)
{
    const auto key = std::make_pair(length, speed);
    auto it = cache.legends.find(key);
    if (it != cache.legends.end()) return it->second;
    const QFont font = labelFont();
    const QFontMetricsF metrics(font);
    const QString label = QStringLiteral("%1 m/s").arg(speed);
    const double h = metrics.height();
    const QRectF box(0.0, 0.0, length + metrics.horizontalAdvance(label) + 28.0, h + 12.0);
    QImage image = blankImage(box.size(), cache.devicePixelRatio);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    QPainterPath path;
    path.addRoundedRect(box, 4.0, 4.0);
    painter.fillPath(path, QColor(0, 0, 0, 150));
    const double y = box.center().y();
    const double x0 = box.left() + 8.0, x1 = x0 + length;
    painter.setPen(QPen(QColor(255, 237, 77), 3.0));
    painter.drawLine(QPointF(x0, y), QPointF(x1, y));
    painter.drawLine(QPointF(x1, y), QPointF(x1 - 7.0, y - 4.0));
    painter.drawLine(QPointF(x1, y), QPointF(x1 - 7.0, y + 4.0));
    painter.setFont(font);
    painter.setPen(Qt::white);
    painter.drawText(QRectF(x1 + 8.0, box.top(), metrics.horizontalAdvance(label) + 4.0, box.height()), Qt::AlignCenter,
                     label);
    painter.end();
    return cache.legends.emplace(key, std::move(image)).first->second;
}

// A bar exactly as long on screen (to the pixel) as a velocity arrow drawn at the middle of the
// table, for the largest round speed whose bar fits in 240 pixels.
void paintVelocityLegend(QPainter& painter, const ViewScene& scene, const LabelFrame& frame, LabelCache& cache)
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
    const int length = static_cast<int>(std::lround(speed * perMetrePerSecond));
    if (length < 4) return;
    const QImage& image = legendImage(cache, length, speed);
    const double h = QFontMetricsF(labelFont()).height();
    painter.drawImage(QPointF(10.0, frame.logicalSize.height() - 2.0 * h - 14.0), image);
}

}  // namespace

void paintOverlayLabels(QPainter& painter, const ViewScene& scene, const LabelFrame& frame)
{
    if (!scene.result) return;
    LabelCache& cache = labelCache(painter.device()->devicePixelRatioF());
    if (frame.overlays.test(static_cast<std::size_t>(Overlay::EventMarkers))) paintEventTimes(painter, scene, frame, cache);
    if (frame.overlays.test(static_cast<std::size_t>(Overlay::Velocities))) paintVelocityLegend(painter, scene, frame, cache);
}

}  // namespace cuelab
