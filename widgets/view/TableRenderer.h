#pragma once
// Draws a ViewScene with OpenGL 3.3 core into the current framebuffer, shared by the TableView widget
// and the offscreen SceneImageRenderer. The caller owns the context: initialize() and release() must
// run with it current, and release() before the context goes away.
//
// One frame is a sequence of passes, each a class with its own RAII-owned GL objects:
//   TablePass    the table (and the cue before the shot), cached per camera;
//   BallPass     contact shadows, then the balls;
//   OverlayPass  ghost balls, paths, markers, constructions, arrows, aim lines, selection;
//   LayerPass    the named view layers (ViewLayer.h).
// Per frame only the ball instances and the lines that depend on the current state are written, into
// buffers that keep their capacity: no allocation per frame.

#include "BallPass.h"
#include "LayerPass.h"
#include "OverlayPass.h"
#include "RenderFrame.h"
#include "ShaderLibrary.h"
#include "TablePass.h"
#include "ViewScene.h"

#include <QString>

#include <optional>
#include <vector>

namespace cuelab {

class TableRenderer {
public:
    TableRenderer();
    ~TableRenderer();
    TableRenderer(const TableRenderer&) = delete;
    TableRenderer& operator=(const TableRenderer&) = delete;

    bool initialize(QString* error);  // compiles the shaders, creates buffers; context current
    void release();                   // frees every GL object; context current
    void setScene(const ViewScene& scene);
    void setLayers(const ViewLayers& layers) { layers_.setLayers(layers); }
    // Where the balls stand before the shot (the document's setup), for the cue stick to keep clear
    // of; empty: the result's.
    void setSetupBalls(const std::vector<Ball>& balls);
    void setVelocityDrag(const std::optional<VelocityDrag>& drag) { velocityDrag_ = drag; }
    void render(const RenderFrame& frame);

    // Whether the last frame drew the table without its cache (the camera had moved since the frame
    // before): the table was not antialiased, and one more frame with the same camera draws it so.
    bool tableUncached() const { return tableUncached_; }

    // The ball states of the last rendered frame (index = ball index).
    const std::vector<BallState>& states() const { return balls_.states(); }

private:
    std::optional<QMatrix4x4> cueModel(const RenderFrame& frame) const;

    ViewScene scene_;
    std::vector<Ball> setupBalls_;
    std::optional<VelocityDrag> velocityDrag_;
    bool initialized_ = false;
    bool tableUncached_ = false;
    ShaderLibrary shaders_;
    TablePass table_;
    BallPass balls_;
    OverlayPass overlays_;
    LayerPass layers_;
};

}  // namespace cuelab
