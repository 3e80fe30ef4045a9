#include "LabelLayout.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace cuelab {

namespace {

constexpr double kGap = 7.0;                    // logical pixels between the anchor and the label's nearest edge
constexpr double kNearReaches[] = {1.0, 2.6, 4.5};  // the near spots, in kGap
// Logical pixels: beyond the farthest near spot (a corner spot at 4.5 kGap across and down: its
// nearest point 4.5 kGap √2 = 44.5 px away) a label needs a leader line.
constexpr double kLeaderBeyond = 4.5 * kGap * std::numbers::sqrt2 + 1.0;
constexpr double kFirstRing = 4.5 * kGap;       // logical pixels: the rings start at the near spots' reach
constexpr int kRingDirections = 16;             // spots per ring around the anchor
constexpr double kRingStep = 14.0;              // logical pixels between rings

QRectF insideView(QRectF box, const QRectF& view)
{
    if (box.right() > view.right()) box.moveRight(view.right());
    if (box.left() < view.left()) box.moveLeft(view.left());
    if (box.bottom() > view.bottom()) box.moveBottom(view.bottom());
    if (box.top() < view.top()) box.moveTop(view.top());
    return box;
}

bool isFree(const QRectF& box, const std::vector<QRectF>& taken)
{
    return std::none_of(taken.begin(), taken.end(), [&box](const QRectF& t) { return t.intersects(box); });
}

// The box of `size` whose nearest point lies `distance` from `anchor` in direction `angle` (radians,
// counter-clockwise on screen from the right), its side facing the anchor.
QRectF boxOnRing(const QPointF& anchor, const QSizeF& size, double distance, double angle)
{
    const double dx = std::cos(angle), dy = -std::sin(angle);  // screen y points down
    const QPointF edge = anchor + distance * QPointF(dx, dy);
    // Moved out by half its size along the direction (saturated), so that the near side faces the anchor.
    const auto push = [](double d) { return std::clamp(2.0 * d, -1.0, 1.0); };
    const QPointF centre = edge + QPointF(push(dx) * size.width() / 2.0, push(dy) * size.height() / 2.0);
    return QRectF(centre - QPointF(size.width() / 2.0, size.height() / 2.0), size);
}

QPointF nearestPoint(const QRectF& box, const QPointF& p)
{
    return QPointF(std::clamp(p.x(), box.left(), box.right()), std::clamp(p.y(), box.top(), box.bottom()));
}

}  // namespace

std::vector<std::optional<QRectF>> layoutLabels(const std::vector<LabelRequest>& requests, const QRectF& view,
                                                const std::vector<QRectF>& reserved)
{
    std::vector<std::optional<QRectF>> placed(requests.size());
    std::vector<std::size_t> order(requests.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&requests](std::size_t a, std::size_t b) { return requests[a].priority > requests[b].priority; });
    std::vector<QRectF> taken = reserved;
    const QRectF inner = view.adjusted(2.0, 2.0, -2.0, -2.0);
    for (std::size_t index : order) {
        const LabelRequest& q = requests[index];
        if (!view.contains(q.anchor)) continue;
        const double w = q.size.width(), h = q.size.height();
        std::optional<QRectF> first;
        for (double reach : kNearReaches) {  // farther out when the near spots are taken (a ball, a label)
            const double g = kGap * reach;
            const QPointF a = q.anchor;
            const QPointF corners[] = {{a.x() + g, a.y() - g - h}, {a.x() + g, a.y() + g},
                                       {a.x() - g - w, a.y() - g - h}, {a.x() - g - w, a.y() + g},
                                       {a.x() - w / 2, a.y() - g - h - 4.0}, {a.x() - w / 2, a.y() + g + 4.0}};
            for (const QPointF& corner : corners) {
                const QRectF box = insideView(QRectF(corner, q.size), inner);
                if (!first) first = box;
                if (isFree(box, taken)) {
                    placed[index] = box;
                    break;
                }
            }
            if (placed[index]) break;
        }
        // A label that must show: the nearest free spot farther out, ring by ring (its leader line
        // ties it back), before giving up and overlapping.
        for (double distance = kFirstRing; q.always && !placed[index] && distance <= kFarthestLabel; distance += kRingStep)
            for (int k = 0; k < kRingDirections && !placed[index]; ++k) {
                const double angle = std::numbers::pi / 4.0 + 2.0 * std::numbers::pi * k / kRingDirections;
                const QRectF box = insideView(boxOnRing(q.anchor, q.size, distance, angle), inner);
                if (isFree(box, taken)) placed[index] = box;
            }
        if (!placed[index] && q.always) placed[index] = first;
        if (placed[index]) taken.push_back(*placed[index]);
    }
    return placed;
}

std::optional<QLineF> leaderLine(const QPointF& anchor, const QRectF& box)
{
    const QPointF end = nearestPoint(box, anchor);
    if (QLineF(anchor, end).length() < kLeaderBeyond) return std::nullopt;
    return QLineF(anchor, end);
}

}  // namespace cuelab
