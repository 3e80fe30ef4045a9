#pragma once
// Renders a scene to an image without a window (QOffscreenSurface + framebuffer object), for
// `cuelab --screenshot`, documentation and tests. Needs a QGuiApplication and OpenGL 3.3 core.

#include "OrbitCamera.h"
#include "ViewLayer.h"
#include "ViewScene.h"

#include <QImage>
#include <QSize>
#include <QString>

#include <bitset>

namespace cuelab {

class TableView;

// The offscreen counterpart of TableView: the same renderer, layers and display switches, drawn on
// demand into an image. Creates its OpenGL context for each render() call (a screenshot is rare).
class SceneImageRenderer {
public:
    void setLayer(const QString& name, ViewLayer layer) { layers_[name] = std::move(layer); }
    void clearLayer(const QString& name) { layers_.erase(name); }
    const ViewLayers& layers() const { return layers_; }
    void setOverlays(std::bitset<kOverlayCount> overlays) { overlays_ = overlays; }
    void setSelectedBall(int index) { selectedBall_ = index; }  // -1 = none
    void setHighlightedEvent(int index) { highlightedEvent_ = index; }  // -1 = none
    void setPathScope(BallScope scope) { pathScope_ = scope; }
    void setLabelScope(BallScope scope) { labelScope_ = scope; }
    std::bitset<kOverlayCount> overlays() const { return overlays_; }
    int selectedBall() const { return selectedBall_; }
    int highlightedEvent() const { return highlightedEvent_; }
    BallScope pathScope() const { return pathScope_; }
    BallScope labelScope() const { return labelScope_; }

    // Draws `scene` at `time` (s) from the camera preset into *out (size pixels). On failure returns
    // false and sets *error to a message a person can act on.
    bool render(const ViewScene& scene, double time, CameraPreset preset, QSize size, QImage* out,
                QString* error) const;
    // The same from a camera pose as it is (the orbit camera's target, distance and rotation; the
    // vertical field of view is the view's, so another aspect ratio shows more or less at the sides).
    bool render(const ViewScene& scene, double time, const CameraPose& pose, QSize size, QImage* out,
                QString* error) const;

private:
    ViewLayers layers_;
    std::bitset<kOverlayCount> overlays_ = defaultOverlays();
    int selectedBall_ = -1;
    int highlightedEvent_ = -1;
    BallScope pathScope_ = BallScope::All;
    BallScope labelScope_ = BallScope::All;
};

// A renderer set up as `view` is now: its layers, overlays, selected ball, highlighted event and
// path and label scopes (File > Export > View as PNG, "Current view").
SceneImageRenderer rendererLike(const TableView& view);
// The table view as it is now, at another size: its camera pose exactly (not a preset), its time and
// everything rendererLike() copies.
bool renderCurrentView(const TableView& view, QSize size, QImage* out, QString* error);

// A SceneImageRenderer with no layers and the overlays that the view shows by default.
bool renderSceneToImage(const ViewScene& scene, double time, CameraPreset preset, QSize size, QImage* out,
                        QString* error);

}  // namespace cuelab
