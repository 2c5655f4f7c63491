#!/usr/bin/env bash
# Install what is missing, build, and run the whole Linux test suite through CTest: every label
# but `soak` (the thousand-round leak loops, scripts/soak.sh; the suite runs them 100 rounds).
# Extra arguments go to ctest (for example: -L unit, or -R camera).
# From a clean clone on a 2-core machine: 8 to 10 minutes with a warm compiler cache, 15 with a cold
# one (docs/testing.md has the figures).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
fractalis_install_packages
fractalis_build
cd "$FRACTALIS_BUILD"
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" -LE soak "$@"
