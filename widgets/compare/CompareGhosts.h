#pragma once
// Another engine's balls as ghosts in the table view (ViewLayer.h): one track per ball through its
// samples, in a colour per engine, ending where the ball drops into a pocket.

#include "Engine.h"
#include "view/ViewLayer.h"

#include <QColor>

namespace cuelab {

QColor engineColour(compare::EngineKind kind);  // discrete magenta, box2d orange, exact cyan

// The layer of `run` (its ghosts labelled with the engine's name on the first ball).
ViewLayer ghostLayer(const compare::EngineRun& run);

}  // namespace cuelab
