#pragma once
// The options that ask for odds under execution noise, shared by `odds` and `sweep --noise`:
// --noise KEY=SIGMA|PRESET (repeatable), --samples N, --seed S, --half-width W; and the odds fields
// of their JSON output.

#include "Command.h"

#include "JsonText.h"
#include "Odds.h"

#include <optional>

namespace cuelab::cli {

// The option specs (for Command::options).
QList<OptionSpec> oddsOptionSpecs();

// Reads the odds options against the loaded setup (tip-offset presets are in radii of the struck
// ball). Returns 0 and sets *request when --noise was given; 0 and leaves it empty when none of the
// options was given; otherwise prints the usage error naming the culprit and returns UsageError.
int readOddsOptions(const Invocation& in, const Setup& setup, std::optional<analysis::OddsRequest>* request);

// "probability": p, "ci95": [lo, hi], "samples": N, "successes": k, then the failures by kind
// ("miscues", "refused", "unfinished") and "stopped_early".
void writeOddsFields(io::JsonWriter& w, const analysis::OddsResult& odds);

}  // namespace cuelab::cli
