#!/usr/bin/env bash
# The long checks that the suite runs shortened: a thousand render-worker restarts and a
# thousand hot reloads (the CTest label `soak`; the suite runs 100 of each), then every fuzz
# target for longer than CI does (scripts/fuzz.sh).
# Usage: scripts/soak.sh [FUZZ_SECONDS_PER_TARGET (default 600; 0 skips fuzzing)]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
fuzz_seconds="${1:-600}"
if ! [[ "$fuzz_seconds" =~ ^[0-9]+$ ]]; then
  echo "fractalis: soak.sh: '$fuzz_seconds' is not a number of seconds" >&2
  exit 2
fi
fractalis_install_packages
fractalis_build
(cd "$FRACTALIS_BUILD" && ctest --output-on-failure -L soak)
if [ "$fuzz_seconds" -gt 0 ]; then
  "$FRACTALIS_ROOT/scripts/fuzz.sh" "$fuzz_seconds"
fi
