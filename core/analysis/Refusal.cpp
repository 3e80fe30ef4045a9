#include "Refusal.h"

#include "NumberText.h"

namespace cuelab::analysis {

std::string refusalMessage(const std::string& setupName, const SetupProblem& problem)
{
    std::string out = setupName.empty() ? std::string("setup") : setupName;
    if (!problem.path.empty()) out += ": " + problem.path;
    return out + ": " + problem.message;
}

std::string roundTrip(double value) { return roundTripText(value); }

std::optional<std::string> unfinishedReason(const SimulationResult& result, const Setup& setup, double until)
{
    if (result.status == SimulationStatus::EventLimit || result.status == SimulationStatus::Cancelled)
        return "the simulation was cut short at t = " + roundTrip(result.endTime) + " s: " + result.error;
    const bool stoppedAtRequest = until >= 0.0 && until <= setup.simulation.maxTime;
    if (result.status == SimulationStatus::ReachedUntil && !stoppedAtRequest)
        return "balls still move at max_time = " + roundTrip(setup.simulation.maxTime) +
               " s (raise simulation.max_time in the setup)";
    return std::nullopt;
}

}  // namespace cuelab::analysis
