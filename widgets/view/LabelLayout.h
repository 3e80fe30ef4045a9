#pragma once
// Places text labels next to their anchor points so that they do not overlap each other (nor the
// reserved boxes, such as a legend) and stay inside the view. Plain geometry on QRectF, no painting.

#include <QPointF>
#include <QRectF>
#include <QSizeF>

#include <optional>
#include <vector>

namespace cuelab {

struct LabelRequest {
    QPointF anchor;       // logical pixels: the point the label belongs to
    QSizeF size;          // logical pixels
    int priority = 0;     // higher first; equal priorities keep their order
    bool always = false;  // placed even when every spot overlaps (then at the first spot, inside the view)
};

// One box per request, in the requests' order: nullopt for a label that found no free spot or whose
// anchor lies outside the view. Each placed box lies inside `view` (when it fits at all). Candidate
// spots are tried in order: right above the anchor, right below, left above, left below, centred
// above, centred below, then the same farther out.
std::vector<std::optional<QRectF>> layoutLabels(const std::vector<LabelRequest>& requests, const QRectF& view,
                                                const std::vector<QRectF>& reserved = {});

}  // namespace cuelab
