#include "OverlayLabels.h"

#include "i18n/UiNumbers.h"

#include "LabelLayout.h"
#include "OverlayLines.h"

#include <QFontMetricsF>
#include <QImage>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
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
    if (x < -1.0 || x > 1.0 || y < -1.0 || y > 1.0) return std::nullopt;  // off screen: no label
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
    std::map<std::pair<QString, QRgb>, QImage> texts;  // layer labels by text and colour
    std::vector<int> order;     // reused every frame
};

LabelCache& labelCache(qreal devicePixelRatio)
{
    static LabelCache cache;
    // Bounded: a new scene brings new times; the cache starts over rather than growing without end.
    constexpr std::size_t kMaxImages = 2048;
    if (cache.devicePixelRatio != devicePixelRatio || cache.tags.size() + cache.legends.size() + cache.texts.size() > kMaxImages) {
        cache.tags.clear();
        cache.texts.clear();
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
    const QString label = QStringLiteral("%1 s").arg(uiNumber(time, 3));
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

QImage textImage(LabelCache& cache, const QString& text, const QColor& ink)
{
    const auto key = std::make_pair(text, ink.rgba());
    auto it = cache.texts.find(key);
    if (it != cache.texts.end()) return it->second;
    const QFont font = labelFont();
    const QFontMetricsF metrics(font);
    const QSizeF size = metrics.size(Qt::TextSingleLine, text) + QSizeF(8.0, 2.0);
    QImage image = blankImage(size, cache.devicePixelRatio);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    QPainterPath path;
    path.addRoundedRect(QRectF(QPointF(0, 0), size), 3.0, 3.0);
    painter.fillPath(path, QColor(0, 0, 0, 175));
    painter.setFont(font);
    QColor opaque = ink;
    opaque.setAlpha(255);
    painter.setPen(opaque.lightnessF() < 0.35 ? QColor(Qt::white) : opaque);
    painter.drawText(QRectF(QPointF(0, 0), size), Qt::AlignCenter, text);
    painter.end();
    return cache.texts.emplace(key, std::move(image)).first->second;
}

struct PendingLabel {
    QImage image;
    LabelRequest request;
    QString text;
};

// Event times, in the label scope, one per instant and neighbourhood on screen.
void collectEventTimes(const ViewScene& scene, const LabelFrame& frame, LabelCache& cache, std::vector<PendingLabel>& out)
{
    const SimulationResult& r = *scene.result;
    struct Shown {
        QString text;
        QPointF at;
    };
    std::vector<Shown> shown;
    std::vector<int>& order = cache.order;
    order.clear();
    // The highlighted event first, so that it always gets its label.
    if (frame.highlightedEvent >= 0 && static_cast<std::size_t>(frame.highlightedEvent) < r.events.size())
        order.push_back(frame.highlightedEvent);
    for (std::size_t e = 0; e < r.events.size(); ++e)
        if (static_cast<int>(e) != frame.highlightedEvent) order.push_back(static_cast<int>(e));
    for (int e : order) {
        const Event& ev = r.events[static_cast<std::size_t>(e)];
        if (!isCollision(ev.kind) && ev.kind != EventKind::BallPocket) continue;
        const bool highlighted = e == frame.highlightedEvent;
        if (!highlighted) {
            if (frame.labelScope == BallScope::None) continue;
            // The selected ball's events only; with no ball selected, none (a cushion event's second
            // agent is -1, which must not match "no selection").
            if (frame.labelScope == BallScope::Selected &&
                (frame.selectedBall < 0 || (ev.balls[0] != frame.selectedBall && ev.balls[1] != frame.selectedBall)))
                continue;
        }
        const Vec2 p = ev.kind == EventKind::BallPocket ? ev.before[0].position : ev.contactPoint;
        const double radius = ev.balls[0] >= 0 ? r.balls[static_cast<std::size_t>(ev.balls[0])].radius : r.table.ballRadius;
        const std::optional<QPointF> at = toScreen(frame, QVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                                                    static_cast<float>(radius)));
        if (!at) continue;
        // One label per instant as the label shows it (to the millisecond): a chain of contacts at
        // one instant (a rack, a break) reads as one time, at its first (or highlighted) event.
        const QString text = QStringLiteral("%1 s").arg(uiNumber(ev.time, 3));
        const bool repeated = std::any_of(shown.begin(), shown.end(), [&](const Shown& s) { return s.text == text; });
        if (repeated && !highlighted) continue;
        shown.push_back({text, *at});
        const TagStyle style = highlighted ? TagStyle::Highlighted : (ev.time > frame.time ? TagStyle::Future : TagStyle::Past);
        const QImage& image = tagImage(cache, ev.time, style);
        out.push_back({image, {*at, image.deviceIndependentSize(), highlighted ? 30 : (style == TagStyle::Past ? 5 : 0), highlighted}, text});
    }
}

// The labels of the view layers, above every event time but the highlighted one.
void collectLayerLabels(const LabelFrame& frame, LabelCache& cache, std::vector<PendingLabel>& out)
{
    if (!frame.layers) return;
    auto add = [&](const QString& text, const QColor& colour, const QVector3D& where) {
        if (text.isEmpty()) return;
        const std::optional<QPointF> at = toScreen(frame, where);
        if (!at) return;
        QImage image = textImage(cache, text, colour);
        out.push_back({image, {*at, image.deviceIndependentSize(), 20, true}, text});
    };
    auto v3 = [](const Vec3& p) { return QVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())); };
    for (const auto& [name, layer] : *frame.layers) {
        if (!layer.visible) continue;
        // A layer's ghosts carry one name (the engine's, on its first ghost): it goes on the first
        // ghost View > Paths Of shows.
        QString ghostName;
        for (const GhostTrack& g : layer.ghosts)
            if (ghostName.isEmpty()) ghostName = g.label;
        for (const GhostTrack& g : layer.ghosts) {
            Vec2 p;
            if (ghostName.isEmpty() || !ghostInScope(g, frame.pathScope, frame.selectedBall) || !ghostPositionAt(g, frame.time, &p))
                continue;
            add(ghostName, g.colour, QVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(2.0 * g.radius)));
            break;
        }
        for (const LayerArrow& a : layer.arrows) add(a.label, a.colour, v3(a.from + a.labelAt * (a.to - a.from)));
        for (const LayerPolyline& l : layer.polylines)
            if (!l.points.empty()) add(l.label, l.colour, v3(l.points.back()));
        for (const LayerMarker& m : layer.markers) add(m.label, m.colour, v3(m.position));
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

// Where the velocity legend goes: a bar exactly as long on screen (to the pixel) as a velocity arrow
// drawn at the middle of the table, for the largest round speed whose bar fits in 240 pixels, in the
// bottom-left corner. Null when the arrows are too short to show.
const QImage* velocityLegend(const ViewScene& scene, const LabelFrame& frame, LabelCache& cache, QPointF* topLeft)
{
    const Table& t = scene.result->table;
    const auto z = static_cast<float>(t.ballRadius);
    const QVector3D centre(static_cast<float>(t.length / 2), static_cast<float>(t.width / 2), z);
    const std::optional<QPointF> a = toScreen(frame, centre);
    const std::optional<QPointF> b = toScreen(frame, centre + QVector3D(static_cast<float>(kVelocityArrowScale), 0, 0));
    const std::optional<QPointF> c = toScreen(frame, centre + QVector3D(0, static_cast<float>(kVelocityArrowScale), 0));
    if (!a || !b || !c) return nullptr;
    const double perMetrePerSecond = std::max(QLineF(*a, *b).length(), QLineF(*a, *c).length());  // pixels
    double speed = 1.0;  // m/s
    for (double candidate : {5.0, 2.0, 1.0, 0.5, 0.2, 0.1, 0.05, 0.02}) {
        speed = candidate;
        if (candidate * perMetrePerSecond <= 240.0) break;
    }
    const int length = static_cast<int>(std::lround(speed * perMetrePerSecond));
    if (length < 4) return nullptr;
    const QImage& image = legendImage(cache, length, speed);
    const double h = QFontMetricsF(labelFont()).height();
    *topLeft = QPointF(10.0, frame.logicalSize.height() - 2.0 * h - 14.0);
    return &image;
}

}  // namespace

OverlayLabelPlan planOverlayLabels(const ViewScene& scene, const LabelFrame& frame, qreal devicePixelRatio)
{
    OverlayLabelPlan plan;
    if (!scene.result) return plan;
    LabelCache& cache = labelCache(devicePixelRatio);
    std::vector<QRectF> reserved;
    QPointF legendAt;
    const QImage* legend = frame.overlays.test(static_cast<std::size_t>(Overlay::Velocities))
                               ? velocityLegend(scene, frame, cache, &legendAt)
                               : nullptr;
    if (legend) {
        reserved.push_back(QRectF(legendAt, legend->deviceIndependentSize()));
        plan.keys.push_back({QStringLiteral("velocity scale"), reserved.back(), *legend});
    }
    // The layers' keys (a scale), apart from every label: stacked in the bottom-left corner, above
    // the velocity legend.
    if (frame.layers) {
        double bottom = legend ? legendAt.y() - 4.0 : frame.logicalSize.height() - 10.0;
        for (const auto& [name, layer] : *frame.layers) {
            if (!layer.visible || layer.legend.isEmpty() || layer.empty()) continue;
            QImage image = textImage(cache, layer.legend, QColor(255, 255, 255));
            const QPointF at(10.0, bottom - image.deviceIndependentSize().height());
            reserved.push_back(QRectF(at, image.deviceIndependentSize()));
            plan.keys.push_back({layer.legend, reserved.back(), std::move(image)});
            bottom = at.y() - 4.0;
        }
    }
    // Labels go around the balls, never over one: each ball's disc on screen is kept free.
    const SimulationResult& r = *scene.result;
    for (std::size_t i = 0; i < r.balls.size(); ++i) {
        const BallState b = r.timelines.empty() ? r.balls[i].state : r.stateAt(static_cast<int>(i), frame.time);
        if (isOutOfPlay(b.motion)) continue;
        const auto radius = static_cast<float>(r.balls[i].radius);
        const QVector3D centre(static_cast<float>(b.position.x()), static_cast<float>(b.position.y()),
                               radius + static_cast<float>(b.z));
        const std::optional<QPointF> at = toScreen(frame, centre);
        if (!at) continue;
        double drawn = 0.0;
        for (const QVector3D& side : {QVector3D(radius, 0, 0), QVector3D(0, radius, 0), QVector3D(0, 0, radius)})
            if (const std::optional<QPointF> rim = toScreen(frame, centre + side)) drawn = std::max(drawn, QLineF(*at, *rim).length());
        drawn += 1.0;  // the outline
        reserved.push_back(QRectF(at->x() - drawn, at->y() - drawn, 2.0 * drawn, 2.0 * drawn));
        plan.balls.push_back(reserved.back());
    }
    std::vector<PendingLabel> labels;
    collectLayerLabels(frame, cache, labels);
    if (frame.overlays.test(static_cast<std::size_t>(Overlay::EventMarkers))) collectEventTimes(scene, frame, cache, labels);
    std::vector<LabelRequest> requests;
    requests.reserve(labels.size());
    for (const PendingLabel& l : labels) requests.push_back(l.request);
    const std::vector<std::optional<QRectF>> boxes =
        layoutLabels(requests, QRectF(QPointF(0, 0), QSizeF(frame.logicalSize)), reserved);
    for (std::size_t k = 0; k < labels.size(); ++k)
        if (boxes[k]) plan.labels.push_back({labels[k].text, *boxes[k], labels[k].image, leaderLine(requests[k].anchor, *boxes[k])});
    return plan;
}

void paintOverlayLabels(QPainter& painter, const ViewScene& scene, const LabelFrame& frame)
{
    const OverlayLabelPlan plan = planOverlayLabels(scene, frame, painter.device()->devicePixelRatioF());
    // Leader lines under the labels: a dark casing and a light core read on every cloth.
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    for (const QColor& ink : {QColor(0, 0, 0, 150), QColor(255, 255, 255, 210)}) {
        const bool casing = ink.lightness() < 128;
        painter.setPen(QPen(ink, casing ? 3.0 : 1.2));
        painter.setBrush(ink);
        for (const OverlayLabelPlan::Item& l : plan.labels)
            if (l.leader) {
                painter.drawLine(*l.leader);
                painter.drawEllipse(l.leader->p1(), casing ? 2.5 : 1.6, casing ? 2.5 : 1.6);
            }
    }
    painter.restore();
    for (const OverlayLabelPlan::Item& l : plan.labels) painter.drawImage(l.box.topLeft(), l.image);
    for (const OverlayLabelPlan::Item& k : plan.keys) painter.drawImage(k.box.topLeft(), k.image);
}

}  // namespace cuelab
