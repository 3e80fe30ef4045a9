#pragma once
// The simulation's overlays: paths and trails, event markers, ghost-ball constructions (built once
// per scene, highlighted event and path scope) and the lines that follow the frame's state (velocity
// arrows, spin indicators, aim lines, the selection ring, a velocity being dragged). A pass of
// TableRenderer: context current in every call.

#include "GlResources.h"
#include "RenderFrame.h"
#include "ShaderLibrary.h"

#include <optional>
#include <vector>

namespace cuelab {

// A velocity being set by dragging its arrow in the view (TableView), drawn as an orange arrow with
// the aim line it gives.
struct VelocityDrag {
    int ball = -1;
    Vec2 from = Vec2::Zero();      // m, the ball's setup position
    Vec2 velocity = Vec2::Zero();  // m/s
};

class OverlayPass {
public:
    void create(unsigned int quadVbo);
    void reset();
    void setScene(const ViewScene& scene);

    // The ghost program bound, with the frame's uniforms.
    void drawGhostBalls(const RenderFrame& frame);
    // The line program bound, with the frame's uniforms.
    void drawLines(QOpenGLShaderProgram& lineProgram, const RenderFrame& frame, const std::vector<BallState>& states,
                   const std::optional<VelocityDrag>& drag);

private:
    void rebuild(const RenderFrame& frame);  // when the scene, highlight or path scope changed
    static int scopeBall(const RenderFrame& frame);  // -1 all, -2 none, else that ball

    ViewScene scene_;
    bool dirty_ = true;
    int builtHighlight_ = -1;
    int builtScope_ = -1;
    LineBatch paths_, markers_, ghostLines_, dynamic_;
    BallBatch ghosts_;
    std::vector<LineVertex> scratch_;
    std::vector<float> instances_;
};

}  // namespace cuelab
