#pragma once
// Where a dragged ball may go: the nearest point to the wanted one that lies on the playing surface
// (the ball's centre at least one radius inside the cushion noses) and does not overlap another ball
// at its setup position. Plain geometry, no Qt.

#include "Simulation.h"

#include <optional>

namespace cuelab {

// Returns nullopt when no free place was found near `wanted` (the ball is boxed in); the caller then
// keeps the last valid position.
std::optional<Vec2> constrainedPlacement(const SimulationResult& result, int ball, const Vec2& wanted);

}  // namespace cuelab
