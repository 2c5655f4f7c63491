#!/usr/bin/env bash
# Install what is missing, build, and run the whole Linux test suite through CTest: every label
# but `soak` (the thousand-round leak loops, scripts/soak.sh; the suite runs them 100 rounds).
# Extra arguments go to ctest (for example: -L unit, or -R camera).
# On a 2-core machine the tests take about 6 minutes with warm caches; from a clean clone with empty
# caches more than 16 (docs/testing.md has the figures).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
fractalis_install_packages
fractalis_build
cd "$FRACTALIS_BUILD"
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" -LE soak "$@"
