#pragma once
// Places text labels next to their anchor points so that they do not overlap each other (nor the
// reserved boxes, such as a legend or a ball) and stay inside the view. Plain geometry on QRectF, no
// painting.

#include <QLineF>
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
    bool always = false;  // placed even when crowded: farther out with a leader line, and only when the
                          // whole view is full, over another label
};

// One box per request, in the requests' order: nullopt for a label that found no free spot or whose
// anchor lies outside the view. Each placed box lies inside `view` (when it fits at all). Candidate
// spots are tried in order: right above the anchor, right below, left above, left below, centred
// above, centred below, then the same farther out. An `always` label that finds none of these free
// (a collision in the centre-of-mass frame crowds seven labels into a few balls' widths) goes on
// the nearest free spot on rings around the anchor, out to kFarthestLabel, with a leader line
// (leaderLine).
std::vector<std::optional<QRectF>> layoutLabels(const std::vector<LabelRequest>& requests, const QRectF& view,
                                                const std::vector<QRectF>& reserved = {});

// Logical pixels: how far from its anchor an `always` label may be put before it overlaps another.
inline constexpr double kFarthestLabel = 220.0;

// The line that ties a label put away from its anchor back to it: from the anchor to the box's
// nearest point; nullopt when the box lies near enough to the anchor to be read as its label
// (one of the near spots).
std::optional<QLineF> leaderLine(const QPointF& anchor, const QRectF& box);

}  // namespace cuelab
