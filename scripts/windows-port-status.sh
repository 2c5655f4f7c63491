#!/usr/bin/env bash
# Which host source files compile for Windows yet (issue 21, in progress): each file of host/
# outside host/platform/ through MinGW-w64's compiler, syntax only, with the header-only
# libraries' Debian headers (toml++, spdlog with its fmt, GLM, nlohmann-json, stb, the OpenCL
# headers) seen through a folder of links in build-windows/. Prints the count and the files that
# do not compile yet, with their first error. Needs g++-mingw-w64-x86-64-posix
# (scripts/test-windows.sh installs it).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
headers="$root/build-windows/linux-headers"
mkdir -p "$headers"
for d in toml++ spdlog fmt glm nlohmann CL stb; do
  [ -e "/usr/include/$d" ] && ln -sfn "/usr/include/$d" "$headers/$d"
done
cd "$root"
total=0
ok=0
while IFS= read -r f; do
  total=$((total + 1))
  if out="$(x86_64-w64-mingw32-g++-posix -std=c++20 -fsyntax-only -Ihost -Isdk/include -Ikernels \
    -I"$headers" -I"$headers/stb" -DSPDLOG_HEADER_ONLY -DFMT_HEADER_ONLY -DTOML_HEADER_ONLY=1 \
    -DFRACTALIS_VERSION='"0"' -DFRACTALIS_BUILD_ROOT='"/"' -DFRACTALIS_PLUGIN_BUILD_DIR='"/"' \
    -DFRACTALIS_PLUGIN_INSTALL_DIR='"/"' -DFRACTALIS_PATHS_SOURCE_DIR='"/"' \
    -DFRACTALIS_PATHS_INSTALL_DIR='"/"' -DFRACTALIS_SCENE_HOST_BUILD_PATH='"/"' \
    -DFRACTALIS_RENDER_WORKER_BUILD_PATH='"/"' -DFRACTALIS_EXECUTABLE_BUILD_PATH='"/"' "$f" 2>&1)"; then
    ok=$((ok + 1))
  else
    echo "not yet: $f: $(grep -m1 -oE 'error: .*' <<<"$out" | cut -c1-100)"
  fi
done < <(find host -name '*.cpp' ! -path 'host/platform/*' ! -name '*_main.cpp' \
  ! -name main.cpp ! -name lsan_suppressions.cpp | sort)
echo "$ok of $total host source files compile for Windows"
