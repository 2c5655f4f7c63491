#!/usr/bin/env bash
# The Windows build, from Linux: installs MinGW-w64 and Wine (Debian packages), cross-builds in
# build-windows/ with cmake/mingw-w64-x86_64.cmake, and runs the tests under Wine.
#
# Issue 21 is in progress: this builds and tests the platform layer (host/platform/, the one
# place that differs between the systems: files and who may change them, folders, shared
# memory, helper processes and their channels, libraries loaded from private copies) and the
# files above it that need nothing else (output files, cache folders, the plugin folder's watch
# and scan, the plugin loader with fractalis-scene-host.exe, the renderer's OpenCL runtime: run
# under Wine through Wine's opencl.dll on this machine's PoCL); README's Windows section says
# what is and is not ported.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

FRACTALIS_PACKAGES=(cmake make ccache g++-mingw-w64-x86-64-posix wine64 googletest opencl-c-headers
  ocl-icd-libopencl1 pocl-opencl-icd)
fractalis_install_packages

FRACTALIS_BUILD="${FRACTALIS_WINDOWS_BUILD:-$FRACTALIS_ROOT/build-windows}"
# Wine's own state (its "C: drive" and registry) lives in the build folder: made on the first
# run (a few seconds), kept for the next.
export WINEPREFIX="$FRACTALIS_BUILD/wine"
export WINEDEBUG=-all
echo "fractalis: cross-building for Windows in $FRACTALIS_BUILD" >&2
fractalis_build -DCMAKE_TOOLCHAIN_FILE="$FRACTALIS_ROOT/cmake/mingw-w64-x86_64.cmake" \
  -DFRACTALIS_PLATFORM_ONLY=ON -DFRACTALIS_WERROR=ON
cd "$FRACTALIS_BUILD"
# Make the prefix and start one lasting wine server, with Wine's own services, before the tests
# run side by side: two test programs that each find no server and no prefix race to make them,
# and the loser fails at start ("wine: chdir to /tmp/wine-…/server-…: No such file or
# directory", seen in CI); and services started by a test would hold its output open for CTest.
echo "fractalis: preparing Wine in $WINEPREFIX" >&2
mkdir -p "$WINEPREFIX"
wineserver -p 900
trap 'wineserver -k 2>/dev/null || true' EXIT
wine wineboot --init
echo "fractalis: the Windows tests under Wine" >&2
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)"
