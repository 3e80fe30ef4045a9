#!/usr/bin/env bash
# Configures (once) and builds CueLab into build/ (incremental on later runs).
#   scripts/build.sh [extra cmake -D options for the first configure]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${CUELAB_BUILD_DIR:-$root/build}
if [ ! -f "$build/CMakeCache.txt" ]; then
  werror=OFF
  [ -n "${CI:-}" ] && werror=ON   # warnings are errors in CI
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCUELAB_WERROR=$werror "$@"
fi
cmake --build "$build" --parallel "$(nproc)"
