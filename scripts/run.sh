#!/usr/bin/env bash
# Install what is missing, build, and run fractalis with the given arguments.
# With no arguments: render the default scene to fractalis.png.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
fractalis_install_packages
fractalis_build
exe="$FRACTALIS_BUILD/host/fractalis"
if [ $# -eq 0 ]; then
  "$exe" render --out fractalis.png
  echo "fractalis: wrote $(pwd)/fractalis.png"
else
  exec "$exe" "$@"
fi
