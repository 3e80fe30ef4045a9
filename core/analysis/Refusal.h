#pragma once
// The words of a refusal and of an unfinished run, shared by `cuelab-cli --set`, the sweep's lines
// and the Analysis dock, so that a refused shot of a sweep reads exactly as `simulate --set` says it.

#include "LegalSetup.h"
#include "Simulation.h"

#include <optional>
#include <string>

namespace cuelab::analysis {

// "cut.json: balls[1].position: overlaps ball \"cue\" by 2.1 mm" (the loader's form; a problem
// about the whole setup has no path).
std::string refusalMessage(const std::string& setupName, const SetupProblem& problem);

// Why a run did not finish, as cuelab-cli says it; nullopt when it did. Stopping at an `until` the
// caller asked for (until >= 0, not beyond max_time) is finishing.
std::optional<std::string> unfinishedReason(const SimulationResult& result, const Setup& setup, double until);

// The shortest text that reads back to exactly `value` ("0.1", "600", "1e-05"): roundTripText
// (core/setup/NumberText.h), the one formatter.
std::string roundTrip(double value);

}  // namespace cuelab::analysis
