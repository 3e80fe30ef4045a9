#pragma once
// The text of the overlays, painted with QPainter over the GL image: the time of impact next to each
// event marker, the labels of the view layers (ghosts, arrows, polylines, markers) and the scale
// legend of the velocity arrows, and the layers' own keys (a scale) apart in the corner. Labels never
// overlap each other, the legends or a ball (they go around it) and stay inside the view
// (LabelLayout; one put away from its anchor in a crowd gets a leader line); event times at one instant (to the millisecond shown: a rack's chain) get one label;
// with Labels Of: Selected Ball Only and no ball selected, only the highlighted event's. Works on a widget after paintGL and on a rendered QImage alike; each label is drawn once
// into an image and reused (see OverlayLabels.cpp).

#include "ViewLayer.h"
#include "ViewScene.h"

#include <QImage>
#include <QLineF>
#include <QMatrix4x4>
#include <QRectF>
#include <QSize>
#include <QString>

#include <bitset>
#include <optional>
#include <vector>

class QPainter;

namespace cuelab {

struct LabelFrame {
    QMatrix4x4 viewProjection;
    QSize logicalSize;  // the painter's coordinate extent
    double time = 0.0;  // s
    std::bitset<kOverlayCount> overlays;
    int highlightedEvent = -1;
    int selectedBall = -1;
    BallScope labelScope = BallScope::All;  // whose event times are labelled (the highlighted one always)
    const ViewLayers* layers = nullptr;     // labels of the layers (may be null)
    BallScope pathScope = BallScope::All;   // whose ghosts are shown (and labelled)
};

// Where every label and key goes (logical pixels), without painting: what paintOverlayLabels draws.
struct OverlayLabelPlan {
    struct Item {
        QString text;
        QRectF box;
        QImage image;
        std::optional<QLineF> leader;  // to the anchor, for a label put away from it (LabelLayout)
    };
    std::vector<Item> labels;  // event times and layer labels
    std::vector<Item> keys;    // the velocity legend and the layers' keys
    std::vector<QRectF> balls; // each ball's disc on screen, kept free of labels
};
OverlayLabelPlan planOverlayLabels(const ViewScene& scene, const LabelFrame& frame, qreal devicePixelRatio = 1.0);

void paintOverlayLabels(QPainter& painter, const ViewScene& scene, const LabelFrame& frame);

}  // namespace cuelab
