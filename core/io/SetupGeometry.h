#pragma once
// The geometric rules of a setup now live in the Qt-free validator (core/setup, LegalSetup.h); this
// header keeps their Qt-side names for the io code and its tests.

#include "LegalSetup.h"

#include <QString>

namespace cuelab::io {

inline constexpr double kOverlapTolerance = cuelab::kOverlapTolerance;  // m (CONTRACT.md)

// A length for a message, in the unit that keeps it readable: "2.1 mm", "35.0 µm", "4.2 nm".
inline QString describeLength(double metres) { return QString::fromStdString(cuelab::describeLength(metres)); }

}  // namespace cuelab::io
