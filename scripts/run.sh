#!/usr/bin/env bash
# Install what is missing, build, and run fractalis with the given arguments.
# With no arguments: open the explorer when a display is available, else render the default
# scene to fractalis.png.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
fractalis_install_packages
fractalis_build
exe="$FRACTALIS_BUILD/host/fractalis"
if [ $# -eq 0 ]; then
  if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
    exec "$exe" explore
  fi
  "$exe" render --out fractalis.png
  echo "fractalis: wrote $(pwd)/fractalis.png (no display here; on a desktop this opens the explorer)"
else
  exec "$exe" "$@"
fi
