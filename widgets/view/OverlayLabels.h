#pragma once
// The text of the overlays, painted with QPainter over the GL image: the time of impact next to each
// event marker, the labels of the view layers (ghosts, arrows, polylines, markers) and the scale
// legend of the velocity arrows. Labels never overlap each other or the legend and stay inside the
// view (LabelLayout); event times at the same instant close together on screen (a rack's chain) get
// one label. Works on a widget after paintGL and on a rendered QImage alike; each label is drawn once
// into an image and reused (see OverlayLabels.cpp).

#include "ViewLayer.h"
#include "ViewScene.h"

#include <QMatrix4x4>
#include <QSize>

#include <bitset>

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
};

void paintOverlayLabels(QPainter& painter, const ViewScene& scene, const LabelFrame& frame);

}  // namespace cuelab
