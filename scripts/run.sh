#!/usr/bin/env bash
# Installs what is missing, builds, and opens CueLab on a bundled example (or on the files given).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
build=${CUELAB_BUILD_DIR:-$root/build}
if [ $# -eq 0 ]; then
  set -- "$root/resources/examples/half-ball-cut.json"
fi
exec "$build/bin/cuelab" "$@"
