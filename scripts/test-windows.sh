#!/usr/bin/env bash
# The Windows build, tested from Linux: cross-builds fractalis for Windows with its tests
# (scripts/windows-build.sh: MinGW-w64, the libraries cross-built from Debian's source packages,
# the same CMake description as Linux's), runs the tests under Wine, then makes the zip
# (scripts/package-windows.sh) and tries it as a user would: unpacked elsewhere, fractalis.exe
# lists and renders its scenes, flies the explorer for a few frames (Xvfb), and a scene built
# with the zip's SDK passes `fractalis check`.
#
# docs/windows.md says which tests run under Wine and what Wine is not.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
source "$FRACTALIS_ROOT/scripts/windows-build.sh"

fractalis_windows_build "${FRACTALIS_WINDOWS_TEST_PACKAGES[@]}"
# The explorer's window needs a display, and Wine's desktop takes the one its server starts
# with: without one, the rest runs again under Xvfb (the build above is then up to date), a
# screen as large as the largest window explorer_window_test opens.
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 3840x2160x24" "$0" "$@"
fi
# Wine's own state (its "C: drive" and registry) lives in the build folder: made on the first
# run (a few seconds), kept for the next.
export WINEPREFIX="$FRACTALIS_BUILD/wine"
export WINEDEBUG=-all
cd "$FRACTALIS_BUILD"
# Make the prefix and start one lasting wine server, with Wine's own services, before the tests
# run side by side: two test programs that each find no server and no prefix race to make them,
# and the loser fails at start ("wine: chdir to /tmp/wine-…/server-…: No such file or
# directory", seen in CI); and services started by a test would hold its output open for CTest.
echo "fractalis: preparing Wine in $WINEPREFIX" >&2
mkdir -p "$WINEPREFIX"
wineserver -p 900 || true  # exits 2 when one is already running for this prefix: fine
trap 'wineserver -k 2>/dev/null || true' EXIT
wine wineboot --init
# Wine's prefix says "Windows 7" unless told otherwise; Windows 10 is what fractalis is for.
wine winecfg -v win10 < /dev/null > /dev/null 2>&1
# With a display, Wine answers a crash with a dialog that waits for a click (the tests crash
# helpers on purpose); Windows' own dialog is kept away by the error mode fractalis gives them.
wine reg add 'HKCU\Software\Wine\WineDbg' /v ShowCrashDialog /t REG_DWORD /d 0 /f \
  < /dev/null > /dev/null 2>&1
echo "fractalis: the Windows tests under Wine" >&2
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)"

echo "fractalis: the Windows zip, unpacked and run under Wine" >&2
zip_file="$("$FRACTALIS_ROOT/scripts/package-windows.sh")"
bash "$FRACTALIS_ROOT/tests/windows_package_test.sh" "$FRACTALIS_ROOT" "$zip_file" \
  "$FRACTALIS_BUILD/package_test"
