#!/usr/bin/env bash
# `fractalis new` as a scene author meets it: a project from the template, written, built and
# installed in one command, that fractalis then lists; a project from every in-tree scene
# (`--from ID`), all built together, each loading with its original's parameter table, and three
# rendering to exactly their originals' pixels; `new` from an installed fractalis (`cmake
# --install` into a prefix); and the refusals — an existing folder (nothing overwritten), a name
# that is no scene id, a name that is taken, an unknown --from, no CMake on the PATH.
# Usage: new_scene_test.sh SOURCE_DIR WORK_DIR FRACTALIS_EXECUTABLE BUILD_DIR
set -euo pipefail
source_dir=$1 work=$2 fractalis=$3 build_dir=$4
rm -rf "$work"
mkdir -p "$work"
export XDG_DATA_HOME="$work/data"
scenes="$XDG_DATA_HOME/fractalis/scenes"
fail() { echo "FAIL: $*"; exit 1; }

echo "== new my_blob: the template, built and installed"
"$fractalis" new my_blob --dir "$work/my_blob" > "$work/new.out" 2> "$work/new.err" \
  || { cat "$work/new.err"; fail "new my_blob"; }
for f in my_blob.c my_blob.cl CMakeLists.txt README.md; do
  [[ -f "$work/my_blob/$f" ]] || fail "missing $f"
done
[[ -f "$scenes/my_blob.so" ]] || fail "not installed into $scenes"
grep -q "fractalis explore --edit $work/my_blob" "$work/new.out" || fail "no next step printed"
"$fractalis" list --plugins "$scenes" --json > "$work/list.json"
python3 - "$work/list.json" <<'PY'
import json, sys
scenes = json.load(open(sys.argv[1]))["scenes"]
assert [s["id"] for s in scenes] == ["my_blob"], scenes
assert [p["key"] for p in scenes[0]["params"]] == ["radius", "ripple", "waves"], scenes[0]["params"]
assert scenes[0]["name"] == "My blob", scenes[0]["name"]
PY

echo "== new copy_ID --from ID for every in-tree scene, built together"
"$fractalis" list --plugins "$build_dir/scenes" --json > "$work/in_tree.json"
ids=$(python3 -c 'import json,sys; print(" ".join(s["id"] for s in json.load(open(sys.argv[1]))["scenes"]))' "$work/in_tree.json")
[[ $(wc -w <<< "$ids") -ge 40 ]] || fail "fewer than 40 in-tree scenes: $ids"
mkdir -p "$work/all"
{
  echo "cmake_minimum_required(VERSION 3.25)"
  echo "project(every_copy C)"
} > "$work/all/CMakeLists.txt"
for id in $ids; do
  "$fractalis" new "copy_$id" --from "$id" --dir "$work/all/$id" --no-build > /dev/null \
    || fail "new copy_$id --from $id"
  echo "add_subdirectory($id)" >> "$work/all/CMakeLists.txt"
done
cmake -S "$work/all" -B "$work/all/build" -DFractalisSDK_DIR="$source_dir/sdk/cmake" \
  -DFRACTALIS_EXECUTABLE="$fractalis" > /dev/null
cmake --build "$work/all/build" -j "$(nproc 2>/dev/null || echo 2)" > "$work/all/build.log" \
  || { tail -30 "$work/all/build.log"; fail "building the copies"; }
"$fractalis" list --plugins "$work/all/build/scenes" --json > "$work/copies.json"
python3 - "$work/in_tree.json" "$work/copies.json" <<'PY'
import json, sys
originals = {s["id"]: s for s in json.load(open(sys.argv[1]))["scenes"]}
copies = {s["id"]: s for s in json.load(open(sys.argv[2]))["scenes"]}
assert not json.load(open(sys.argv[2])).get("failed"), "a copy failed to load"
for id, original in originals.items():
    copy = copies.get("copy_" + id)
    assert copy is not None, "copy_%s did not load" % id
    for key in ("params", "tags", "credit", "description", "bounding_radius"):
        assert copy.get(key) == original.get(key), "copy_%s: %s differs" % (id, key)
print(len(copies), "copies load with their originals' tables")
PY
for id in menger mandelbox hybrid; do
  "$fractalis" render --plugins "$build_dir/scenes" --scene "$id" --size 96x54 --out "$work/$id.png" > /dev/null
  "$fractalis" render --plugins "$work/all/build/scenes" --scene "copy_$id" --size 96x54 \
    --out "$work/copy_$id.png" > /dev/null
  cmp -s "$work/$id.png" "$work/copy_$id.png" || fail "copy_$id does not render as $id does"
done

echo "== refusals: nothing written, a clear message"
echo "mine" > "$work/my_blob/my_blob.cl.keep"
cp "$work/my_blob/my_blob.cl" "$work/before.cl"
expect_refusal() {  # WHAT EXPECTED_TEXT ARGS...
  local what=$1 text=$2
  shift 2
  if "$fractalis" new "$@" > "$work/refused.out" 2>&1; then fail "$what: accepted"; fi
  grep -q -- "$text" "$work/refused.out" || { cat "$work/refused.out"; fail "$what: no '$text'"; }
}
expect_refusal "an existing folder" "already exists" other_blob --dir "$work/my_blob" --no-build
cmp -s "$work/before.cl" "$work/my_blob/my_blob.cl" || fail "an existing project was written over"
[[ -f "$work/my_blob/my_blob.cl.keep" ]] || fail "an existing file went"
expect_refusal "a bad name" "cannot be a scene id" Bad-Name --no-build
expect_refusal "a taken name" "there is a scene 'menger' already" menger --no-build
expect_refusal "a taken name (the user's)" "there is a scene 'my_blob' already" my_blob --no-build
expect_refusal "an unknown --from" "is no in-tree scene" x1 --from no_such_scene --no-build
expect_refusal "no NAME" "NAME is required" --no-build
[[ ! -e "$work/data/fractalis/scene-sources/x1" ]] || fail "a refused project was written"
# No CMake on the PATH: the project is written, the message says what is missing.
if PATH=/nonexistent "$fractalis" new no_cmake --dir "$work/no_cmake" > "$work/no_cmake.out" 2>&1; then
  fail "built without CMake"
fi
grep -q "CMake is not on the PATH" "$work/no_cmake.out" || { cat "$work/no_cmake.out"; fail "no_cmake"; }
[[ -f "$work/no_cmake/no_cmake.cl" ]] || fail "the project was not written"

echo "== new from an installed fractalis"
cmake --install "$build_dir" --prefix "$work/prefix" > /dev/null
[[ -f "$work/prefix/share/fractalis/scene-sources/julia/julia.cl" ]] || fail "scene sources not installed"
XDG_DATA_HOME="$work/data2" "$work/prefix/bin/fractalis" new installed_julia --from julia \
  --dir "$work/installed_julia" > /dev/null 2> "$work/installed.err" \
  || { cat "$work/installed.err"; fail "new from the installed fractalis"; }
[[ -f "$work/data2/fractalis/scenes/installed_julia.so" ]] || fail "installed_julia not installed"
grep -q "FractalisSDK_DIR:[A-Z]*=$work/prefix" "$work/installed_julia/build/CMakeCache.txt" \
  || fail "built against another SDK than the prefix's"
XDG_DATA_HOME="$work/data2" "$work/prefix/bin/fractalis" list --search installed_julia \
  | grep -q "installed_julia" || fail "the installed fractalis does not list it"
echo "new_scene_test: ok"
