#pragma once
// The checks of a parsed setup that need the table geometry: a table whose rails have room for its
// pockets, cushions lower than the balls, and every ball on the playing surface without overlapping
// a cushion, a jaw, a pocket or another ball.

#include "Setup.h"
#include "SetupProblem.h"

#include <optional>

namespace cuelab::io {

// Two bodies may overlap by at most this much: a frozen rack touches "exactly" only up to rounding.
inline constexpr double kOverlapTolerance = 1e-9;  // m (CONTRACT.md)

// The first problem found, in the order of the balls; nullopt when the setup can be simulated.
// `table` is makeTable(setup.table), which the caller has at hand already.
std::optional<SetupProblem> checkGeometry(const Setup& setup, const Table& table);

// A length for a message, in the unit that keeps it readable: "2.1 mm", "35 µm", "4.2 nm".
QString describeLength(double metres);

}  // namespace cuelab::io
