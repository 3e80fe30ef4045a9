#pragma once
// What one frame of the renderer is drawn for: the camera, the viewport, the time and the view's
// switches. Filled by the table view and by the offscreen renderer; read by every pass.

#include "ViewScene.h"

#include <QMatrix4x4>
#include <QSize>
#include <QVector3D>

#include <bitset>

namespace cuelab {

struct RenderFrame {
    QMatrix4x4 viewProjection;
    QVector3D eye;         // m
    QVector3D cameraUp;    // unit, the screen's up in the world
    float pixelAngle = 0;  // radians per pixel (vertical field of view / viewport height)
    QSize viewportPixels;  // framebuffer pixels
    float devicePixelRatio = 1.0f;  // framebuffer pixels per logical pixel
    double time = 0.0;     // s
    std::bitset<kOverlayCount> overlays;
    int selectedBall = -1;
    int highlightedEvent = -1;
    BallScope pathScope = BallScope::All;  // whose paths, trails, markers and ghost constructions
};

// Radians per pixel of an image `heightPixels` high seen through the orbit camera.
float pixelAngle(int heightPixels);

}  // namespace cuelab
