#pragma once
// The shot's outcome in one line for people, translated (the status bar, the Outcome dock's header,
// the shot diagram's caption): the same facts as core/outcome's outcomeSummary(), which the CLI and
// the files keep in English, with pockets named as a person reads them ("top-right pocket").

#include "ShotOutcome.h"
#include "Simulation.h"

#include <QString>

namespace cuelab {

QString outcomeLine(const SimulationResult& result, const ShotOutcome& outcome);

}  // namespace cuelab
