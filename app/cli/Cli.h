#pragma once

#include <QStringList>

namespace cuelab::cli {

// Runs cuelab-cli with `arguments` (argv, program name first). Writes to stdout/stderr and returns
// the exit status of CONTRACT.md: 0 success, 1 setup refused, 2 usage error, 3 simulation failed.
int run(const QStringList& arguments);

}  // namespace cuelab::cli
