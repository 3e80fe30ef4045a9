#pragma once
// The one round-trip number formatter: the shortest decimal text that reads back to exactly the same
// double (std::to_chars without a format: "0.1", "600", "1e-05", "-0"; locale-free). JSON output
// (core/io JsonText: roundTripNumber, which writes null for what JSON cannot hold), refusal and
// unfinished-run messages, --set values and the comparison's warnings all print numbers with it.
// Plain std: no Qt.

#include <string>

namespace cuelab {

// "0.1", "600", "1e-05", "-0"; not-a-number and infinities as to_chars writes them ("nan", "inf",
// "-inf").
std::string roundTripText(double value);

}  // namespace cuelab
