#include "SceneFraming.h"

#include "TableMesh.h"

namespace cuelab {

PresetFrame presetFrameFor(const ViewScene& scene, float aspect)
{
    PresetFrame frame;
    frame.aspect = aspect;
    if (!scene.result) return frame;
    const SimulationResult& r = *scene.result;
    frame.extent = tableExtent(r.table);
    const QPointF centre = frame.extent.center();
    frame.focus = QVector3D(static_cast<float>(centre.x()), static_cast<float>(centre.y()), 0.0f);
    int ball = scene.shot ? r.ballIndex(scene.shot->ball) : r.ballIndex("cue");
    if (ball < 0 && !r.balls.empty()) ball = 0;
    if (ball >= 0) {
        const Vec2 p = r.balls[static_cast<std::size_t>(ball)].state.position;
        frame.focus = QVector3D(static_cast<float>(p.x()), static_cast<float>(p.y()), 0.0f);
    }
    frame.headingDeg = scene.shot ? static_cast<float>(scene.shot->headingDeg) : 0.0f;
    return frame;
}

}  // namespace cuelab
