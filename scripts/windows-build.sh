# Sourced by scripts/test-windows.sh and scripts/package-windows.sh: the Windows build, from
# Linux (fractalis_windows_build), with the Debian packages it needs and the libraries fractalis
# builds with, for Windows. Debian ships them for Linux only (MinGW-w64 gets zlib alone), so
# they are cross-built here from Debian's own source packages (`apt-get source`: the same
# versions and patches as the Linux build uses) and installed into one prefix,
# $FRACTALIS_WINDOWS_DEPS/prefix, where the toolchain file (cmake/mingw-w64-x86_64.cmake) makes
# CMake find them as it finds /usr on Linux. Each library is built once: a stamp names the
# version it was built from, so a new Debian version is built again and nothing else is.
#
# The prefix lives in the user's cache folder, not in the checkout, so a fresh clone (CI's) finds
# it built: $XDG_CACHE_HOME/fractalis/windows-deps/KEY, where KEY is a digest of the MinGW-w64
# packages' versions, the toolchain file and this script (a new compiler or recipe gets a
# prefix of its own). A checksum list written when the prefix is complete is checked before each
# use; a prefix that fails it is built again. A lock keeps two builds from writing one prefix.
#
# Not here: FFmpeg with x264 and libvpx (video needs all three cross-built, too much for CI's
# time), OpenEXR with Imath (not yet) — the Windows build refuses those outputs with the reason
# and writes PNG (CMakeLists.txt: FRACTALIS_VIDEO, FRACTALIS_OPENEXR) — and MPI (Microsoft MPI
# is not in Debian; one machine only).

FRACTALIS_BUILD="${FRACTALIS_WINDOWS_BUILD:-$FRACTALIS_ROOT/build-windows}"
FRACTALIS_TOOLCHAIN="$FRACTALIS_ROOT/cmake/mingw-w64-x86_64.cmake"

# Sets FRACTALIS_WINDOWS_DEPS (unless the caller chose one) and FRACTALIS_WINDOWS_PREFIX, once
# the toolchain is installed: the cache folder keyed as the header says.
fractalis_windows_deps_folder() {
  if [ -z "${FRACTALIS_WINDOWS_DEPS:-}" ]; then
    local key
    key="$({
      dpkg-query -W -f='${Package} ${Version}\n' g++-mingw-w64-x86-64-posix \
        gcc-mingw-w64-x86-64-posix-runtime mingw-w64-x86-64-dev binutils-mingw-w64-x86-64 \
        libz-mingw-w64-dev 2>/dev/null
      sha256sum "$FRACTALIS_TOOLCHAIN" "$FRACTALIS_ROOT/scripts/windows-build.sh" | cut -d' ' -f1
    } | sha256sum | cut -c1-16)"
    FRACTALIS_WINDOWS_DEPS="${XDG_CACHE_HOME:-$HOME/.cache}/fractalis/windows-deps/$key"
  fi
  FRACTALIS_WINDOWS_PREFIX="$FRACTALIS_WINDOWS_DEPS/prefix"
  mkdir -p "$FRACTALIS_WINDOWS_DEPS"
}

# The prefix's checksum list: every file under it, in a stable order.
fractalis_windows_manifest() {
  (cd "$FRACTALIS_WINDOWS_PREFIX" && find . -type f -print0 | LC_ALL=C sort -z |
    xargs -0 -r sha256sum)
}

# `apt-get source` needs source lists, which a Debian image often lacks: the same mirror and
# release as the binary packages, as one more list of our own.
fractalis_source_lists() {
  apt-cache showsrc --only-source libsdl2 2>/dev/null | grep -q '^Version:' && return 0
  if [ "$(id -u)" -ne 0 ]; then
    echo "fractalis: apt has no source lists (deb-src), needed to cross-build the libraries" >&2
    echo "for Windows; add them (as root: scripts/test-windows.sh does it) and run again" >&2
    exit 1
  fi
  local codename
  codename="$(. /etc/os-release && echo "$VERSION_CODENAME")"
  echo "fractalis: adding Debian's source lists ($codename) for apt-get source" >&2
  cat >/etc/apt/sources.list.d/fractalis-deb-src.sources <<EOF
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: $codename $codename-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg

Types: deb-src
URIs: http://deb.debian.org/debian-security
Suites: $codename-security
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
EOF
  apt-get update -qq
}

# The versions of source package $1 to try, best first: the one built into Linux's binary
# package $2 where it is installed (the same code on both systems), then the others apt knows,
# newest first (a mirror may lack some: Debian's security archive keeps only the latest).
fractalis_source_versions() {
  local package="$1" binary="$2"
  {
    dpkg-query -W -f='${source:Version}\n' "$binary" 2>/dev/null || true
    apt-cache showsrc --only-source "$package" | sed -n 's/^Version: //p' | sort -rV
  } | awk 'NF && !seen[$0]++'
}

# Unpacks Debian's source package $1 (patches applied) and prints its folder and version, or
# nothing when one of its versions is already built into the prefix.
fractalis_fetch_source() {
  local package="$1" binary="$2" version folder
  local versions
  versions="$(fractalis_source_versions "$package" "$binary")"
  for version in $versions; do
    [ -f "$FRACTALIS_WINDOWS_DEPS/stamps/$package-$version" ] && return 0
  done
  rm -rf "$FRACTALIS_WINDOWS_DEPS/src/$package"
  mkdir -p "$FRACTALIS_WINDOWS_DEPS/src/$package"
  for version in $versions; do
    if (cd "$FRACTALIS_WINDOWS_DEPS/src/$package" &&
      apt-get source -qq "$package=$version" >/dev/null 2>&1); then
      folder="$(find "$FRACTALIS_WINDOWS_DEPS/src/$package" -mindepth 1 -maxdepth 1 -type d | head -1)"
      echo "$folder $version"
      return 0
    fi
    rm -rf "${FRACTALIS_WINDOWS_DEPS:?}/src/$package"/*
  done
  echo "fractalis: apt-get source $package failed for every version apt knows ($(echo $versions))" >&2
  return 1
}

fractalis_stamp() {
  local package="$1" version="$2"
  mkdir -p "$FRACTALIS_WINDOWS_DEPS/stamps"
  rm -f "$FRACTALIS_WINDOWS_DEPS/stamps/$package-"*
  touch "$FRACTALIS_WINDOWS_DEPS/stamps/$package-$version"
  rm -rf "$FRACTALIS_WINDOWS_DEPS/src/$package" "$FRACTALIS_WINDOWS_DEPS/build/$package"
}

# A CMake project from source folder $2, as package $1, static, into the prefix. With
# FRACTALIS_INSTALL_ONLY=1 nothing is built, only installed: for a header-only library whose
# project builds its own tests whatever BUILD_TESTING says (Debian's GLM: a thousand test
# programs, minutes of compiling for nothing).
fractalis_cmake_install() {
  local package="$1" source="$2"
  shift 2
  local build="$FRACTALIS_WINDOWS_DEPS/build/$package"
  echo "fractalis: cross-building $package for Windows" >&2
  mkdir -p "$build"
  cmake -S "$source" -B "$build" -DCMAKE_TOOLCHAIN_FILE="$FRACTALIS_TOOLCHAIN" \
    -DFRACTALIS_WINDOWS_PREFIX="$FRACTALIS_WINDOWS_PREFIX" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_INSTALL_PREFIX="$FRACTALIS_WINDOWS_PREFIX" -DBUILD_SHARED_LIBS=OFF \
    -DCMAKE_POLICY_DEFAULT_CMP0077=NEW "$@" >"$build.log" 2>&1 &&
    { [ "${FRACTALIS_INSTALL_ONLY:-0}" = 1 ] ||
      cmake --build "$build" -j "$(nproc 2>/dev/null || echo 2)" >>"$build.log" 2>&1; } &&
    cmake --install "$build" >>"$build.log" 2>&1 || {
    tail -30 "$build.log" >&2
    echo "fractalis: cross-building $package failed (the whole log: $build.log)" >&2
    exit 1
  }
}

# Source package $1 (Linux's binary package $2), a CMake project, built and installed.
fractalis_cmake_package() {
  local package="$1" binary="$2" fetched
  shift 2
  fetched="$(fractalis_fetch_source "$package" "$binary")"
  [ -z "$fetched" ] && return 0
  fractalis_cmake_install "$package" "${fetched% *}" "$@"
  fractalis_stamp "$package" "${fetched##* }"
}

# Dear ImGui has no build system of its own (Debian's package adds a Makefile for Linux): its
# core and the SDL2 backend compiled into libimgui.a, its headers where Linux has them
# (include/imgui), and the SDL_Renderer backend's source where host/CMakeLists.txt compiles it
# from, as on Linux (Debian ships that one as an example). Its .pc file names no SDL2: SDL2's own
# CMake package brings the static library and what it needs.
fractalis_build_imgui() {
  local fetched source
  fetched="$(fractalis_fetch_source imgui libimgui-dev)"
  [ -z "$fetched" ] && return 0
  source="${fetched% *}"
  echo "fractalis: cross-building imgui for Windows" >&2
  local build="$FRACTALIS_WINDOWS_DEPS/build/imgui" prefix="$FRACTALIS_WINDOWS_PREFIX" f
  mkdir -p "$build" "$prefix/lib/pkgconfig" "$prefix/include/imgui/backends" \
    "$prefix/share/imgui/backends"
  local pids=() pid
  for f in imgui.cpp imgui_draw.cpp imgui_tables.cpp imgui_widgets.cpp imgui_demo.cpp \
    backends/imgui_impl_sdl.cpp; do
    x86_64-w64-mingw32-g++-posix -O2 -c "$source/$f" -I"$source" -I"$prefix/include/SDL2" \
      -w -o "$build/$(basename "$f" .cpp).o" &
    pids+=($!)
  done
  for pid in "${pids[@]}"; do
    wait "$pid" || {
      echo "fractalis: cross-building imgui failed" >&2
      exit 1
    }
  done
  rm -f "$prefix/lib/libimgui.a"
  x86_64-w64-mingw32-ar rcs "$prefix/lib/libimgui.a" "$build"/*.o
  cp "$source"/*.h "$prefix/include/imgui/"
  cp "$source"/backends/imgui_impl_sdl*.h "$prefix/include/imgui/backends/"
  cp "$source/backends/imgui_impl_sdlrenderer.cpp" "$prefix/share/imgui/backends/"
  cat >"$prefix/lib/pkgconfig/imgui.pc" <<EOF
prefix=$prefix
Name: imgui
Description: Dear ImGui, cross-built from Debian's source package
Version: $(sed -n 's/^#define IMGUI_VERSION  *"\(.*\)"/\1/p' "$source/imgui.h")
Libs: -L\${prefix}/lib -limgui
Cflags: -I\${prefix}/include/imgui
EOF
  fractalis_stamp imgui "${fetched##* }"
}

# The OpenCL import library: MinGW-w64 has none for OpenCL.dll (a driver's or PoCL's, installed
# on the user's PC), so it is made from the functions fractalis calls (cmake/OpenCL.def), with
# the Khronos headers of Debian's opencl-c-headers (the same declarations on every system).
fractalis_opencl_import() {
  local prefix="$FRACTALIS_WINDOWS_PREFIX"
  mkdir -p "$prefix/lib" "$prefix/include"
  if [ ! -f "$prefix/lib/libOpenCL.dll.a" ] || [ "$FRACTALIS_ROOT/cmake/OpenCL.def" -nt "$prefix/lib/libOpenCL.dll.a" ]; then
    x86_64-w64-mingw32-dlltool -d "$FRACTALIS_ROOT/cmake/OpenCL.def" \
      -l "$prefix/lib/libOpenCL.dll.a" -D OpenCL.dll
  fi
  rm -rf "$prefix/include/CL"
  cp -r /usr/include/CL "$prefix/include/CL"
}

# toml++: its source package is gone from Debian's mirror (404) while its binary package is
# installed; it is a header-only library with an optional compiled mode, and Debian's headers
# serve in the header-only mode, under the CMake name Linux finds it by.
fractalis_tomlplusplus() {
  local prefix="$FRACTALIS_WINDOWS_PREFIX"
  rm -rf "$prefix/include/toml++"
  cp -r /usr/include/toml++ "$prefix/include/toml++"
  mkdir -p "$prefix/lib/cmake/tomlplusplus"
  cat >"$prefix/lib/cmake/tomlplusplus/tomlplusplusConfig.cmake" <<'EOF'
# Written by scripts/windows-build.sh: Debian's toml++ headers, header-only.
if(NOT TARGET tomlplusplus::tomlplusplus)
  add_library(tomlplusplus::tomlplusplus INTERFACE IMPORTED)
  set_target_properties(tomlplusplus::tomlplusplus PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${CMAKE_CURRENT_LIST_DIR}/../../../include"
    INTERFACE_COMPILE_DEFINITIONS "TOML_HEADER_ONLY=1")
endif()
EOF
}

# stb_image, for the tests (they read back with it what fractalis wrote with libpng): Debian's
# libstb-dev is its headers plus the implementation compiled for Linux; the same here, from
# those headers, under the same pkg-config name.
fractalis_stb() {
  local prefix="$FRACTALIS_WINDOWS_PREFIX" build="$FRACTALIS_WINDOWS_DEPS/build/stb"
  [ -f "$prefix/lib/libstb.a" ] && [ "$prefix/lib/libstb.a" -nt /usr/include/stb/stb_image.h ] &&
    return 0
  echo "fractalis: cross-building stb_image for Windows" >&2
  mkdir -p "$build" "$prefix/include/stb" "$prefix/lib/pkgconfig"
  cp /usr/include/stb/stb_image.h "$prefix/include/stb/"
  printf '#define STB_IMAGE_IMPLEMENTATION\n#include <stb_image.h>\n' >"$build/stb_image.c"
  x86_64-w64-mingw32-gcc-posix -O2 -w -c "$build/stb_image.c" -I"$prefix/include/stb" \
    -o "$build/stb_image.o"
  x86_64-w64-mingw32-ar rcs "$prefix/lib/libstb.a" "$build/stb_image.o"
  cat >"$prefix/lib/pkgconfig/stb.pc" <<EOF
prefix=$prefix
Name: stb
Description: stb_image, from Debian's libstb-dev headers
Version: 0.0
Libs: -L\${prefix}/lib -lstb
Cflags: -I\${prefix}/include/stb
EOF
}

fractalis_windows_deps() {
  local manifest="$FRACTALIS_WINDOWS_DEPS/manifest.sha256"
  if [ -f "$manifest" ]; then
    if [ "$(fractalis_windows_manifest)" = "$(cat "$manifest")" ]; then
      echo "fractalis: the Windows libraries, cached in $FRACTALIS_WINDOWS_DEPS, verified" >&2
    else
      echo "fractalis: the cached Windows libraries in $FRACTALIS_WINDOWS_DEPS differ from their" \
        "checksum list; building them again" >&2
      rm -rf "${FRACTALIS_WINDOWS_DEPS:?}/prefix" "$FRACTALIS_WINDOWS_DEPS/stamps" "$manifest"
    fi
  fi
  rm -f "$manifest"
  fractalis_source_lists
  fractalis_opencl_import
  fractalis_cmake_package fmtlib libfmt-dev -DFMT_DOC=OFF -DFMT_TEST=OFF
  fractalis_cmake_package spdlog libspdlog-dev -DSPDLOG_FMT_EXTERNAL=ON -DSPDLOG_BUILD_EXAMPLE=OFF \
    -DSPDLOG_BUILD_TESTS=OFF -DSPDLOG_BUILD_BENCH=OFF
  FRACTALIS_INSTALL_ONLY=1 fractalis_cmake_package glm libglm-dev -DBUILD_TESTING=OFF
  fractalis_tomlplusplus
  fractalis_cmake_package nlohmann-json3 nlohmann-json3-dev -DJSON_BuildTests=OFF
  fractalis_cmake_package libpng1.6 libpng-dev -DPNG_SHARED=OFF -DPNG_TESTS=OFF \
    -DZLIB_ROOT=/usr/x86_64-w64-mingw32
  fractalis_cmake_package libsdl2 libsdl2-dev -DSDL_SHARED=OFF -DSDL_STATIC=ON -DSDL_TEST=OFF
  fractalis_build_imgui
  fractalis_stb
  # GoogleTest from Debian's googletest package (its source, installed in /usr/src).
  local gtest_version
  gtest_version="$(dpkg-query -W -f='${Version}' googletest)"
  if [ ! -f "$FRACTALIS_WINDOWS_DEPS/stamps/googletest-$gtest_version" ]; then
    fractalis_cmake_install googletest /usr/src/googletest -DINSTALL_GTEST=ON -DBUILD_GMOCK=OFF
    fractalis_stamp googletest "$gtest_version"
  fi
  fractalis_windows_manifest >"$manifest.part"
  mv -f "$manifest.part" "$manifest"
}

# Everything: the packages (MinGW-w64, the source tools, the headers some libraries come from),
# the libraries, then fractalis itself in $FRACTALIS_BUILD, with the tests; extra arguments go to
# cmake's first configure.
FRACTALIS_WINDOWS_PACKAGES=(cmake make ccache pkg-config dpkg-dev g++-mingw-w64-x86-64-posix
  libz-mingw-w64-dev googletest opencl-c-headers libtomlplusplus-dev libstb-dev)
# What the Windows tests and the zip's test need besides (scripts/test-windows.sh; .ci/run installs
# both lists with Linux's, up front).
FRACTALIS_WINDOWS_TEST_PACKAGES=(wine64 ocl-icd-libopencl1 pocl-opencl-icd zip unzip xvfb xauth)
fractalis_windows_build() {
  FRACTALIS_PACKAGES=("${FRACTALIS_WINDOWS_PACKAGES[@]}" "$@")
  fractalis_install_packages
  fractalis_windows_deps_folder
  (
    flock 9
    fractalis_windows_deps
  ) 9>"$FRACTALIS_WINDOWS_DEPS/lock"
  echo "fractalis: cross-building for Windows in $FRACTALIS_BUILD" >&2
  # A build folder configured with another prefix (an older key) is pointed at this one.
  if [ -f "$FRACTALIS_BUILD/CMakeCache.txt" ] && [ "$FRACTALIS_WINDOWS_PREFIX" != \
    "$(sed -n 's/^FRACTALIS_WINDOWS_PREFIX:[A-Z]*=//p' "$FRACTALIS_BUILD/CMakeCache.txt")" ]; then
    cmake -S "$FRACTALIS_ROOT" -B "$FRACTALIS_BUILD" \
      -DFRACTALIS_WINDOWS_PREFIX="$FRACTALIS_WINDOWS_PREFIX" >&2
  fi
  fractalis_build -DCMAKE_TOOLCHAIN_FILE="$FRACTALIS_TOOLCHAIN" \
    -DFRACTALIS_WINDOWS_PREFIX="$FRACTALIS_WINDOWS_PREFIX" -DFRACTALIS_WERROR=ON
}
