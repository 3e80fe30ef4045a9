#pragma once
// Draws the named ViewLayers (ViewLayer.h): ghost balls at the frame's time, their paths, arrows,
// polylines and markers. The paths and polylines are built once per change of the layers; the
// ghosts, arrows (heads turned to the camera) and markers (facing it) every frame. The labels are
// painted by OverlayLabels. A pass of TableRenderer: context current in every call.

#include "GlResources.h"
#include "RenderFrame.h"
#include "ViewLayer.h"

#include <vector>

class QOpenGLShaderProgram;

namespace cuelab {

class LayerPass {
public:
    void create(unsigned int quadVbo);
    void reset();
    void setLayers(const ViewLayers& layers);
    const ViewLayers& layers() const { return layers_; }
    bool empty() const;

    // The ghost program bound, with the frame's uniforms.
    void drawGhosts(const RenderFrame& frame);
    // The line program bound, with the frame's uniforms.
    void drawLines(QOpenGLShaderProgram& lineProgram, const RenderFrame& frame);

    // Line runs of one width, in a batch.
    struct Run {
        float width = 2.0f;  // logical pixels
        int first = 0;
        int count = 0;
        bool dashedFuture = false;  // a ghost path: solid before the frame's time, dashed after
    };

private:
    ViewLayers layers_;
    bool staticDirty_ = true;
    BallScope shownScope_ = BallScope::All;  // the ghost paths in the cache follow View > Paths Of
    int shownSelected_ = -1;
    LineBatch staticLines_, dynamicLines_;
    BallBatch ghosts_;
    std::vector<Run> staticRuns_, dynamicRuns_;
    std::vector<LineVertex> scratch_;
    std::vector<float> instances_;
};

}  // namespace cuelab
