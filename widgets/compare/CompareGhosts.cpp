#include "CompareGhosts.h"

namespace cuelab {

QColor engineColour(compare::EngineKind kind)
{
    switch (kind) {
    case compare::EngineKind::Discrete: return QColor(235, 60, 210, 140);
    case compare::EngineKind::Box2D: return QColor(255, 150, 20, 140);
    case compare::EngineKind::Exact: return QColor(60, 220, 255, 140);
    }
    return QColor(255, 255, 255, 120);
}

ViewLayer ghostLayer(const compare::EngineRun& run)
{
    ViewLayer layer;
    const QColor colour = engineColour(run.settings.engine);
    for (std::size_t i = 0; i < run.ids.size(); ++i) {
        GhostTrack& g = layer.ghosts.emplace_back();
        g.radius = run.radii[i];
        g.colour = colour;
        g.ball = static_cast<int>(i);  // the runs keep the setup's ball order
        if (i == 0) g.label = QString::fromUtf8(compare::toString(run.settings.engine).data());
        for (std::size_t k = 0; k < run.samples.size(); ++k) {
            const compare::BallSample& s = run.samples[k][i];
            g.times.push_back(run.sampleTime(k));
            g.positions.push_back(s.position);
            if (s.pocketed) break;  // gone: the ghost disappears at the pocket
        }
        // A ball that came to rest stays where it is for the rest of the transport.
        if (!run.samples.empty() && !run.samples.back()[i].pocketed) {
            g.times.push_back(1e6);
            g.positions.push_back(run.samples.back()[i].position);
        }
    }
    return layer;
}

}  // namespace cuelab
