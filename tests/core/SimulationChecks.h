#pragma once
// The shared checks of whole simulation results now live in the soak library (tests/soak/Checks.h,
// one copy for the core suites, the fuzz targets and cuelab-bench --soak); this header keeps the
// suites' includes working.

#include "Checks.h"
