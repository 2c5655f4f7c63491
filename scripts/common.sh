# Shared by scripts/run.sh and scripts/test.sh: install what is missing, then build.
# Sourced, not run. Every step says what it does; any failure stops the caller.

FRACTALIS_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
FRACTALIS_BUILD="${FRACTALIS_BUILD:-$FRACTALIS_ROOT/build}"

# ccache hashes paths inside the checkout relative to it, and not the build folder's own path, so
# that a clone elsewhere (a CI run's) reuses what another clone compiled.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$FRACTALIS_ROOT}"
export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"

# The Debian packages the project builds, runs and tests with.
FRACTALIS_PACKAGES=(
  cmake g++ make pkg-config ccache lld
  ocl-icd-opencl-dev opencl-c-headers pocl-opencl-icd
  libglm-dev libspdlog-dev libtomlplusplus-dev libstb-dev libpng-dev libsdl2-dev libimgui-dev
  xvfb xauth
  libgtest-dev libbenchmark-dev
  nlohmann-json3-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev ffmpeg
  libopenexr-dev
  clang libclang-rt-14-dev
  libopenmpi-dev openmpi-bin
  mandelbulber2 mandelbulber2-data  # the import's independent answer and its 422 example files
)

fractalis_missing_packages() {
  local pkg missing=()
  for pkg in "${FRACTALIS_PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$pkg")
    fi
  done
  echo "${missing[@]}"
}

fractalis_install_packages() {
  local missing
  missing="$(fractalis_missing_packages)"
  [ -z "$missing" ] && return 0
  if [ "$(id -u)" -ne 0 ]; then
    echo "fractalis: missing Debian packages: $missing" >&2
    echo "Install them with:" >&2
    echo "  sudo apt-get update && sudo apt-get install -y $missing" >&2
    exit 1
  fi
  echo "fractalis: installing $missing" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $missing >/dev/null
}

# Configure once, build incrementally afterwards. Extra arguments go to cmake's configure.
fractalis_build() {
  local jobs
  jobs="$(nproc 2>/dev/null || echo 2)"
  if [ ! -f "$FRACTALIS_BUILD/CMakeCache.txt" ]; then
    cmake -S "$FRACTALIS_ROOT" -B "$FRACTALIS_BUILD" -DCMAKE_BUILD_TYPE=Release "$@" >&2
  fi
  cmake --build "$FRACTALIS_BUILD" -j "$jobs" >&2
}
