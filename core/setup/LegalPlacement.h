#pragma once
// Where a ball may go: the legal spot nearest to the one the user wanted (a drop on a rack, a drag
// against a cushion, a table change that leaves balls outside). "Legal" is LegalSetup's rule, with a
// small gap kept to everything so that a ball put down by hand does not touch unless asked to.

#include "Setup.h"

#include <optional>
#include <vector>

namespace cuelab {

// The gap kept between a ball put down by hand and every other body or edge. Far above the file
// format's 1e-9 m overlap tolerance (so rounding never turns the spot illegal), far below anything
// a person can see (so the ball lands where it was meant to).
inline constexpr double kPlacementGap = 1e-6;  // m

// The centre nearest to `wanted` where a ball of radius `radius` is legal on `table` among the balls
// `others` (at their positions; the one at index `skip`, if any, is ignored: the ball itself). When
// `wanted` itself is legal it is returned unchanged; otherwise the answer keeps at least `gap` from
// every ball, cushion nose, jaw tip, pocket circle and edge of the playing surface. It is exact:
// the nearest point of the free region lies on one boundary (the foot of a perpendicular or the
// nearest or farthest point of a circle) or where two boundaries cross, and every such candidate is
// tried. nullopt when nowhere on the table is free (or the table or radius admit no legal place).
std::optional<Vec2> nearestLegalSpot(const Table& table, const std::vector<Ball>& others, double radius,
                                     const Vec2& wanted, double gap = kPlacementGap, int skip = -1);

// The same for ball `index` of `setup`, the other balls at their setup positions.
std::optional<Vec2> nearestLegalSpot(const Setup& setup, std::size_t index, const Vec2& wanted,
                                     double gap = kPlacementGap);

// Whether a ball of radius `radius` at `p` is legal on `table` among `others` (skipping index `skip`)
// by the rules of LegalSetup (1e-9 m overlap tolerance).
bool isLegalSpot(const Table& table, const std::vector<Ball>& others, double radius, const Vec2& p, int skip = -1);

}  // namespace cuelab
