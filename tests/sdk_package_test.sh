#!/usr/bin/env bash
# The SDK as a third-party author gets it: installed on its own (nothing of the host built) into a
# Debian multiarch prefix, then the template scene built out of tree against it with
# find_package(FractalisSDK 1.0) and checked with `fractalis check`; the template also builds
# against the source tree's package; and a version the SDK does not satisfy is refused.
# Usage: sdk_package_test.sh SOURCE_DIR WORK_DIR FRACTALIS_EXECUTABLE
set -euo pipefail
source_dir=$1 work=$2 fractalis=$3
rm -rf "$work"
mkdir -p "$work"
prefix="$work/prefix"

echo "== SDK alone, installed with a multiarch libdir"
cmake -S "$source_dir/sdk" -B "$work/sdk-build" -DCMAKE_INSTALL_PREFIX="$prefix" \
  -DCMAKE_INSTALL_LIBDIR=lib/x86_64-linux-gnu > /dev/null
cmake --install "$work/sdk-build" --component sdk > /dev/null
for f in include/fractalis/abi.h lib/x86_64-linux-gnu/cmake/FractalisSDK/FractalisSDKConfig.cmake \
    lib/x86_64-linux-gnu/cmake/FractalisSDK/FractalisSDKConfigVersion.cmake \
    share/fractalis/opencl/prelude.cl share/fractalis/opencl/fr/primitives.cl \
    share/doc/fractalis-sdk/writing-a-scene.md share/doc/fractalis-sdk/template/CMakeLists.txt; do
  [[ -f "$prefix/$f" ]] || { echo "missing after install: $f"; exit 1; }
done
if find "$work/sdk-build" -name '*.o' | grep -q .; then echo "installing the SDK built code"; exit 1; fi

echo "== the template against the installed SDK, then fractalis check"
cmake -S "$prefix/share/doc/fractalis-sdk/template" -B "$work/template-build" \
  -DCMAKE_PREFIX_PATH="$prefix" -DFRACTALIS_EXECUTABLE="$fractalis" > /dev/null
cmake --build "$work/template-build" > /dev/null
ctest --test-dir "$work/template-build" --output-on-failure

echo "== the template against the source tree's package"
cmake -S "$source_dir/sdk/template" -B "$work/template-source" \
  -DFractalisSDK_DIR="$source_dir/sdk/cmake" -DFRACTALIS_EXECUTABLE="$fractalis" > /dev/null
cmake --build "$work/template-source" > /dev/null
"$fractalis" check "$work/template-source/scenes/my_scene.so" > /dev/null

echo "== version checks: 1.0 found, 2.0 and 1.99 refused"
mkdir -p "$work/version"
for want in 1.0 2.0 1.99; do
  cat > "$work/version/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.25)
project(version_probe LANGUAGES C)
find_package(FractalisSDK $want REQUIRED)
CMAKE
  if cmake -S "$work/version" -B "$work/version/build-$want" -DCMAKE_PREFIX_PATH="$prefix" \
      > "$work/version/log-$want" 2>&1; then found=yes; else found=no; fi
  expected=no; [[ $want == 1.0 ]] && expected=yes
  [[ $found == "$expected" ]] || { echo "find_package(FractalisSDK $want): found=$found"; cat "$work/version/log-$want"; exit 1; }
done

echo "== the whole project, configured and not built: its sdk component installs, under --prefix"
cmake -S "$source_dir" -B "$work/whole" -DFRACTALIS_TESTS=OFF > /dev/null
cmake --install "$work/whole" --component sdk --prefix "$work/prefix2" > /dev/null
if find "$work/whole" -name '*.o' -o -name 'fractalis' -type f | grep -q .; then
  echo "the whole project built something"; exit 1
fi
[[ -f "$work/prefix2/include/fractalis/abi.h" ]] || { echo "component install missed the headers"; exit 1; }
if find "$work/prefix2" -path '*plugins*' | grep -q .; then echo "scenes escaped the sdk component"; exit 1; fi
echo "== the template against that prefix (plain lib/ layout)"
cmake -S "$source_dir/sdk/template" -B "$work/template-lib" -DCMAKE_PREFIX_PATH="$work/prefix2" \
  -DFRACTALIS_EXECUTABLE="$fractalis" > /dev/null
cmake --build "$work/template-lib" > /dev/null
[[ -f "$work/template-lib/scenes/my_scene.so" ]] || { echo "no scene built against prefix2"; exit 1; }
echo "sdk package: ok"
