#!/usr/bin/env bash
# Install what is missing, build, and run the test suite through CTest.
# Extra arguments go to ctest (for example: -L unit, or -R camera).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
fractalis_install_packages
fractalis_build
cd "$FRACTALIS_BUILD"
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" "$@"
