#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test. GUI tests need a real X server:
# the whole ctest run happens inside Xvfb (QOpenGLWidget crashes under QT_QPA_PLATFORM=offscreen;
# Mesa's llvmpipe under Xvfb gives OpenGL 4.5).
#   scripts/test.sh [ctest arguments, e.g. -R tst_table]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
build=${CUELAB_BUILD_DIR:-$root/build}
xvfb=(xvfb-run -a -s "-screen 0 1920x1200x24")
if [ $# -gt 0 ]; then
  "${xvfb[@]}" ctest --test-dir "$build" --output-on-failure --timeout 900 "$@"
  exit
fi
# Every test: those without a window on every core at once, then the GUI tests one at a time (they
# share one X server, and several wait for their window to be the active one).
jobs=$(nproc)
status=0
"${xvfb[@]}" ctest --test-dir "$build" --output-on-failure --timeout 900 -LE gui -j "$jobs" || status=$?
"${xvfb[@]}" ctest --test-dir "$build" --output-on-failure --timeout 900 -L gui || status=$?
exit $status
