#pragma once
// The text of the overlays, painted with QPainter over the GL image: the time of impact next to each
// event marker and the scale legend of the velocity arrows. Works on a widget after paintGL and on a
// rendered QImage alike; each label is drawn once into an image and reused (see OverlayLabels.cpp).

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
};

void paintOverlayLabels(QPainter& painter, const ViewScene& scene, const LabelFrame& frame);

}  // namespace cuelab
