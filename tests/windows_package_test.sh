#!/usr/bin/env bash
# The Windows zip as a user gets it, under Wine (scripts/test-windows.sh runs this): unpacked into
# a folder with a space in its name, fractalis.exe finds its own scenes and helpers from where it
# lies (nothing of the build tree), lists and renders them, opens the explorer's window for a
# few frames (Xvfb), refuses the outputs this build lacks with the reason, and a scene built with
# the zip's SDK (MinGW-w64, the template) passes `fractalis check`.
# Usage: windows_package_test.sh SOURCE_DIR ZIP WORK_DIR   (WINEPREFIX and DISPLAY set, wine
# running)
set -euo pipefail
source_dir=$1 zip=$2 work=$3
rm -rf "$work"
mkdir -p "$work/Program Files"
unzip -q "$zip" -d "$work/Program Files"
root="$(find "$work/Program Files" -mindepth 1 -maxdepth 1 -type d)"
exe="$root/bin/fractalis.exe"
fail() { echo "windows package: $*" >&2; exit 1; }
# Wine holds its console's pipes open after the program ends: output goes to files.
fractalis() { wine "$exe" "$@" < /dev/null > "$work/out.txt" 2> "$work/err.txt"; }

for f in bin/fractalis.exe libexec/fractalis/fractalis-scene-host.exe \
    libexec/fractalis/fractalis-render-worker.exe lib/fractalis/plugins/mandelbulb.dll \
    share/fractalis/paths/benchmark.toml include/fractalis/abi.h \
    lib/cmake/FractalisSDK/FractalisSDKConfig.cmake README.txt settings-example.toml; do
  [[ -f "$root/$f" ]] || fail "missing from the zip: $f"
done
# Statically linked: nothing beyond Windows' own DLLs and OpenCL.dll.
for f in "$root"/bin/*.exe "$root"/libexec/fractalis/*.exe; do
  deps="$(x86_64-w64-mingw32-objdump -p "$f" | sed -n 's/^\s*DLL Name: //p' | tr 'A-Z' 'a-z' |
    grep -vxE 'kernel32.dll|user32.dll|gdi32.dll|advapi32.dll|shell32.dll|ole32.dll|oleaut32.dll|imm32.dll|winmm.dll|version.dll|setupapi.dll|msvcrt.dll|opencl.dll|ws2_32.dll|shlwapi.dll|dinput8.dll|cfgmgr32.dll' || true)"
  [[ -z "$deps" ]] || fail "$(basename "$f") needs DLLs the zip lacks: $deps"
done

echo "== list: every in-tree scene (plugins/ID/), found beside the executable"
fractalis list || fail "list failed: $(cat "$work/err.txt")"
grep -q "plugin folder: .*lib.fractalis.plugins" "$work/out.txt" ||
  fail "list did not use the zip's scenes: $(head -1 "$work/out.txt")"
for folder in "$source_dir"/plugins/*/; do
  scene="$(basename "$folder")"
  grep -q "^$scene " "$work/out.txt" || fail "list lacks $scene"
done

echo "== render: a PNG, through the render worker and Wine's opencl.dll"
fractalis render --scene menger --size 96x64 --out "Z:$work/menger.png" ||
  fail "render failed: $(cat "$work/err.txt")"
[[ "$(head -c 8 "$work/menger.png" | od -An -tx1 | tr -d ' \n')" == 89504e470d0a1a0a ]] ||
  fail "menger.png is not a PNG"

echo "== animate: a camera path into a folder of PNG frames; bench; sweep; cache"
fractalis animate --scene benchmark --path "$root/share/fractalis/paths/benchmark.toml" --fps 1 \
  --size 64x32 --out "Z:$work/frames" || fail "animate failed: $(cat "$work/err.txt")"
frames=$(find "$work/frames" -name 'frame_*.png' | wc -l)
[[ $frames == 21 ]] || fail "animate wrote $frames frames, not the 21 of 20 s at 1 fps"
fractalis bench --scene julia --size 64x36 --frames 3 --runs 1 ||
  fail "bench failed: $(cat "$work/err.txt")"
grep -q "median" "$work/out.txt" || fail "bench said: $(cat "$work/out.txt")"
fractalis sweep --scene menger --size 48x32 --knobs max_steps --frames 1 --out "Z:$work/sweep" ||
  fail "sweep failed: $(cat "$work/err.txt")"
for f in sweep.csv sweep.json sweep.svg; do [[ -s "$work/sweep/$f" ]] || fail "sweep wrote no $f"; done
fractalis cache || fail "cache failed: $(cat "$work/err.txt")"
grep -qi "kernels" "$work/out.txt" || fail "cache said: $(cat "$work/out.txt")"

echo "== explore: the window (SDL2 through Wine's X11 driver), the overlay, 20 frames"
[[ -n "${DISPLAY:-}" ]] || fail "no DISPLAY (scripts/test-windows.sh runs this under Xvfb)"
fractalis explore --frames 20 --size 320x180 || fail "explore failed: $(cat "$work/err.txt")"
grep -q "explored for 20 frames" "$work/out.txt" || fail "explore: $(cat "$work/out.txt")"

echo "== hot reload: a scene DLL dropped into the watched folder appears in the running explorer"
mkdir -p "$work/scenes"
cp "$root/lib/fractalis/plugins/mandelbulb.dll" "$work/scenes/"
wine "$exe" explore --plugins "Z:$work/scenes" --frames 100000 --size 160x90 < /dev/null \
  > "$work/out.txt" 2> "$work/err.txt" &
explorer=$!
# Files there when the explorer starts are loaded, not added: drop the new one once it runs (it
# starts in about 2 s here).
sleep 10
cp "$root/lib/fractalis/plugins/menger.dll" "$work/scenes/"
for _ in $(seq 60); do grep -q "added 'menger' from menger.dll" "$work/err.txt" && break; sleep 0.5; done
kill "$explorer" 2>/dev/null || true
wait "$explorer" 2>/dev/null || true
grep -q "added 'menger' from menger.dll" "$work/err.txt" ||
  fail "the dropped scene was not added: $(cat "$work/err.txt")"

echo "== outputs this build lacks: refused before rendering, with the reason"
if fractalis render --scene menger --size 96x64 --out "Z:$work/x.exr"; then fail "EXR accepted"; fi
grep -q "built without OpenEXR" "$work/err.txt" || fail "EXR refusal: $(cat "$work/err.txt")"
[[ ! -e "$work/x.exr" ]] || fail "an EXR file appeared"
if fractalis animate --scene benchmark --path "$root/share/fractalis/paths/benchmark.toml" \
    --size 64x32 --out "Z:$work/x.mp4"; then fail "video accepted"; fi
grep -q "built without FFmpeg" "$work/err.txt" || fail "video refusal: $(cat "$work/err.txt")"

echo "== a scene from the zip's SDK (the template, MinGW-w64), checked by fractalis check"
cmake -S "$root/share/doc/fractalis-sdk/template" -B "$work/template" \
  -DCMAKE_TOOLCHAIN_FILE="$source_dir/cmake/mingw-w64-x86_64.cmake" \
  -DFractalisSDK_DIR="$root/lib/cmake/FractalisSDK" > "$work/template.log" 2>&1 ||
  fail "the template did not configure: $(tail -5 "$work/template.log")"
cmake --build "$work/template" > "$work/template.log" 2>&1 ||
  fail "the template did not build: $(tail -5 "$work/template.log")"
[[ -f "$work/template/scenes/my_scene.dll" ]] || fail "no my_scene.dll"
fractalis check "Z:$work/template/scenes/my_scene.dll" ||
  fail "check failed: $(cat "$work/out.txt" "$work/err.txt")"
echo "windows package: ok"
