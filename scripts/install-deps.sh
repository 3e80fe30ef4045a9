#!/usr/bin/env bash
# Installs exactly the Debian 12 packages CueLab needs to build, run and test, and nothing else.
# Idempotent: installs only what is missing, and says what it installs. Uses sudo when not root.
#   scripts/install-deps.sh            what building, running and testing CueLab needs
#   scripts/install-deps.sh --cluster  and also a batch scheduler for tests/cluster (CI runs it)
set -euo pipefail

packages=(
  cmake ninja-build g++                      # build tools
  ccache                                     # one compiler cache shared by every build folder
  qt6-base-dev qt6-base-dev-tools            # Qt 6.4: Core, Gui, Widgets, OpenGL, Test
  libqt6opengl6-dev                          # Qt6::OpenGLWidgets (QOpenGLWidget)
  libgl-dev libgl1-mesa-dri                  # OpenGL headers; Mesa's llvmpipe software renderer
  libeigen3-dev                              # Eigen 3.4 (the physics core's only dependency)
  zlib1g-dev                                 # zlib: shot codes (core/io/ShotCode.cpp)
  qt6-charts-dev                             # Qt Charts: plots, error and polynomial charts
  qt6-svg-dev                                # Qt SVG: shot diagrams (QSvgGenerator) and their tests
  qt6-l10n-tools qt6-tools-dev               # Qt Linguist tools: lupdate/lrelease and their CMake (Qt6LinguistTools)
  qt6-translations-l10n                      # Qt's own translations (qtbase_hu.qm: standard buttons and dialogs)
  libbox2d-dev                               # Box2D 2.4, the comparison engine of core/compare
  libnlopt-cxx-dev                           # NLopt 2.7: derivative-free searches of core/fit (with libnlopt-dev)
  pkg-config libavcodec-dev libavformat-dev libswscale-dev  # FFmpeg 5.1: slow-motion video (widgets/video; H.264, VP9, GIF)
  clang libclang-rt-14-dev                   # libFuzzer (-fsanitize=fuzzer) for the fuzz targets
  desktop-file-utils appstream               # desktop-file-validate, appstreamcli (install checks)
  dpkg-dev file                              # cpack -G DEB (dpkg-shlibdeps, file)
  xvfb xauth                                 # a real X server for the GUI tests (xvfb-run)
)

# tests/cluster/slurm-sweep.sh: a one-node Slurm cluster on localhost and GNU parallel run the sweep
# scripts of docs/analysis.md. Not needed to build or use CueLab.
cluster_packages=(
  slurmctld slurmd slurm-client munge        # Slurm 22.05 and its authentication daemon
  parallel                                   # GNU parallel
)
case "${1:-}" in
  "") ;;
  --cluster) packages+=("${cluster_packages[@]}") ;;
  *) echo "install-deps: unknown option '$1' (expected nothing or --cluster)" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: not root and no sudo; install: ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
