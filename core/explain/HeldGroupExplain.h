#pragma once
// Held contacts and held groups in an explanation (internal to core/explain; HeldGroupExplain.cpp).

#include "Explain.h"

namespace cuelab::explain::detail {

// The event settled a held group (a hold, a group solved with it, or other balls' states changed).
bool carriesHeldGroup(const Event& ev);
// The group's derivation, in place of the short account of it (or before the energy step): its rows,
// the re-seating's complementarity problem and its impulses, the forces of the next segment, and
// each ball's velocity and spin after. Nothing when the run again does not record the group; a step
// that says the solve is left out, with no numbers, when the limits stopped the run again.
void addHeldGroupSteps(const SimulationResult& r, int index, const std::optional<CueStrike>& shot,
                       const ExplainLimits& limits, Explanation& e);

}  // namespace cuelab::explain::detail
