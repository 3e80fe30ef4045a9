#pragma once
// Where a dragged or dropped ball may go: the legal spot nearest to the wanted one. Legal as the
// setup loader has it (core/io SetupGeometry, tolerance 1e-9 m): the centre on the playing surface,
// not in a pocket, at least a radius from every cushion nose, off every jaw and every other ball.
// Plain geometry, no Qt.
//
// The nearest legal spot is exact, not a push along a line of centres: the free region's boundary is
// made of circles (other balls, jaws, pockets, the rounded ends of cushion noses) and straight lines
// (cushion noses, the surface's edges), so the nearest free point to the wanted one is the wanted
// point itself, its projection on one boundary piece, or a corner where two pieces meet. Every such
// candidate is checked and the nearest legal one wins; a ball dropped onto a rack lands in the gap
// next to the cursor, not behind the rack.

#include "Simulation.h"

#include <optional>
#include <vector>

namespace cuelab {

// Spots are kept this far from contact, so that they stay legal after a round trip through a file.
inline constexpr double kPlacementMargin = 1e-7;  // m

// Whether `ball` (an index into `balls`) may stand at `p` with the other balls where they are.
bool isLegalSpot(const Table& table, const std::vector<Ball>& balls, int ball, const Vec2& p);

// The legal spot nearest to `wanted`; nullopt when there is none on the table (or `ball` is out of
// range). Other balls stay where `balls` has them (the document's current setup).
std::optional<Vec2> nearestLegalSpot(const Table& table, const std::vector<Ball>& balls, int ball, const Vec2& wanted);

// The same against a simulation result's table and setup balls.
std::optional<Vec2> constrainedPlacement(const SimulationResult& result, int ball, const Vec2& wanted);

}  // namespace cuelab
