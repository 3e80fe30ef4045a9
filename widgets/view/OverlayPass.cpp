#include "OverlayPass.h"

#include <QOpenGLShaderProgram>

namespace cuelab {

void OverlayPass::create(unsigned int quadVbo)
{
    for (LineBatch* b : {&paths_, &markers_, &ghostLines_, &dynamic_}) b->create();
    ghosts_.create(quadVbo);
    dirty_ = true;
}

void OverlayPass::reset()
{
    for (LineBatch* b : {&paths_, &markers_, &ghostLines_, &dynamic_}) b->reset();
    ghosts_.reset();
    dirty_ = true;
}

void OverlayPass::setScene(const ViewScene& scene)
{
    scene_ = scene;
    dirty_ = true;
}

int OverlayPass::scopeBall(const RenderFrame& frame)
{
    switch (frame.pathScope) {
    case BallScope::All: return -1;
    case BallScope::Selected: return frame.selectedBall >= 0 ? frame.selectedBall : -2;
    case BallScope::None: return -2;
    }
    return -1;
}

void OverlayPass::rebuild(const RenderFrame& frame)
{
    const int only = scopeBall(frame);
    scratch_.clear();
    instances_.clear();
    if (scene_.result) {
        const SimulationResult& r = *scene_.result;
        if (only != -2) buildPathLines(r, scratch_, only);
        else scratch_.clear();
        paths_.upload(scratch_);
        // With no ball in scope, only the highlighted event keeps its marker.
        buildEventMarkers(r, frame.highlightedEvent, scratch_, only == -2 ? static_cast<int>(r.balls.size()) : only);
        markers_.upload(scratch_);
        if (only != -2) buildGhostLines(r, scratch_, only);
        else scratch_.clear();
        ghostLines_.upload(scratch_);
        const float identity[4] = {0, 0, 0, 1};
        if (only != -2)
            for (const GhostBall& g : ghostBalls(r, only))
                appendBallInstance(instances_, g.centre, g.radius, identity, QVector3D(0.92f, 0.92f, 0.95f), 0, false, false,
                                   false, 0.28f);
    } else {
        for (LineBatch* b : {&paths_, &markers_, &ghostLines_}) b->upload(scratch_);
    }
    ghosts_.upload(instances_);
    builtHighlight_ = frame.highlightedEvent;
    builtScope_ = only;
    dirty_ = false;
}

void OverlayPass::drawGhostBalls(const RenderFrame& frame)
{
    if (dirty_ || builtHighlight_ != frame.highlightedEvent || builtScope_ != scopeBall(frame)) rebuild(frame);
    if (frame.overlays.test(static_cast<std::size_t>(Overlay::GhostBalls))) ghosts_.draw();
}

void OverlayPass::drawLines(QOpenGLShaderProgram& lineProgram, const RenderFrame& frame,
                            const std::vector<BallState>& states, const std::optional<VelocityDrag>& drag)
{
    if (dirty_ || builtHighlight_ != frame.highlightedEvent || builtScope_ != scopeBall(frame)) rebuild(frame);
    auto on = [&frame](Overlay o) { return frame.overlays.test(static_cast<std::size_t>(o)); };
    scratch_.clear();
    if (scene_.result) {
        const SimulationResult& r = *scene_.result;
        if (on(Overlay::Velocities)) appendVelocityArrows(r, states, scratch_);
        if (on(Overlay::Spin)) appendSpinIndicators(r, states, scratch_);
        if (frame.time <= 0.0 && on(Overlay::CueAndAim) && !drag) appendAimLines(r, scene_.shot, scratch_);
        if (drag) appendVelocityDragArrow(r, drag->ball, drag->from, drag->velocity, scratch_);
        appendSelectionRing(r, states, frame.selectedBall, scratch_);
    }
    dynamic_.upload(scratch_);

    paths_.draw(lineProgram, 2.5f, on(Overlay::Trails) ? 1.0f : 0.0f, on(Overlay::FuturePaths) ? 0.75f : 0.0f, 0.035f);
    if (on(Overlay::GhostBalls)) ghostLines_.draw(lineProgram, 2.0f, 1.0f, 0.5f, 0.0f);
    if (on(Overlay::EventMarkers)) markers_.draw(lineProgram, 2.5f, 1.0f, 0.45f, 0.0f);
    dynamic_.draw(lineProgram, 3.0f, 1.0f, 1.0f, 0.0f);
}

}  // namespace cuelab
