#include "LabelLayout.h"

#include <algorithm>
#include <numeric>

namespace cuelab {

namespace {

constexpr double kGap = 7.0;  // logical pixels between the anchor and the label's nearest edge

QRectF insideView(QRectF box, const QRectF& view)
{
    if (box.right() > view.right()) box.moveRight(view.right());
    if (box.left() < view.left()) box.moveLeft(view.left());
    if (box.bottom() > view.bottom()) box.moveBottom(view.bottom());
    if (box.top() < view.top()) box.moveTop(view.top());
    return box;
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
        for (double reach : {1.0, 2.6, 4.5}) {  // farther out when the near spots are taken (a ball, a label)
            const double g = kGap * reach;
            const QPointF a = q.anchor;
            const QPointF corners[] = {{a.x() + g, a.y() - g - h}, {a.x() + g, a.y() + g},
                                       {a.x() - g - w, a.y() - g - h}, {a.x() - g - w, a.y() + g},
                                       {a.x() - w / 2, a.y() - g - h - 4.0}, {a.x() - w / 2, a.y() + g + 4.0}};
            for (const QPointF& corner : corners) {
                const QRectF box = insideView(QRectF(corner, q.size), inner);
                if (!first) first = box;
                const bool free = std::none_of(taken.begin(), taken.end(), [&box](const QRectF& t) { return t.intersects(box); });
                if (free) {
                    placed[index] = box;
                    break;
                }
            }
            if (placed[index]) break;
        }
        if (!placed[index] && q.always) placed[index] = first;
        if (placed[index]) taken.push_back(*placed[index]);
    }
    return placed;
}

}  // namespace cuelab
