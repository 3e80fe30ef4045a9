#pragma once
// The ball pass: every ball at the frame's time as a lit, numbered impostor with its contact shadow.
// Owns the unit quad shared by every impostor batch (balls, ghost balls, layer ghosts) and the digit
// atlas the numbers are read from. A pass of TableRenderer: context current in every call.

#include "BallAppearance.h"
#include "BallOrientations.h"
#include "GlResources.h"
#include "RenderFrame.h"
#include "ShaderLibrary.h"

#include <vector>

namespace cuelab {

class BallPass {
public:
    void create();
    void reset();
    unsigned int quadBuffer() const { return quad_.id(); }
    unsigned int digitTexture() const { return digits_.id(); }

    // The balls' looks and orientation of a new result.
    void setScene(const ViewScene& scene);
    // Evaluates every ball at the frame's time and uploads the instances. The states stay readable.
    void update(const RenderFrame& frame);
    const std::vector<BallState>& states() const { return states_; }

    void drawShadows(const RenderFrame& frame, ShaderLibrary& shaders);
    void drawBalls(const RenderFrame& frame, ShaderLibrary& shaders, const std::array<QVector3D, 2>& lamps);

private:
    void createDigitTexture();

    std::shared_ptr<const SimulationResult> result_;
    std::vector<BallLook> looks_;  // per ball
    BallOrientations orientations_;
    std::vector<BallState> states_;
    std::vector<float> instances_;  // reused every frame
    GlBuffer quad_;
    BallBatch balls_;
    GlVertexArray shadowVao_;
    GlTexture digits_;
};

}  // namespace cuelab
