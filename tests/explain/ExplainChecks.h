#pragma once
// Checks that an explanation agrees with the simulation it explains: each step's named results
// equal the event's numbers (1e-12 relative), t0 + root is the event time, and the time-of-impact
// polynomial equals the gap computed from the balls' exact positions (stateAt). Returns the
// disagreements as text (empty when all agree), so a test can also prove that a drift is caught.

#include "Explain.h"
#include "Simulation.h"

#include <string>
#include <vector>

namespace cuelab::testing {

std::vector<std::string> checkExplanation(const SimulationResult& r, const explain::Explanation& e);

}  // namespace cuelab::testing
