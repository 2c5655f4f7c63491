#!/usr/bin/env bash
# Build the libFuzzer programs (clang, ASan + UBSan) and run each target for a bounded time,
# starting from its corpus in fuzz/corpus/. New inputs the fuzzer finds go to a scratch folder,
# not into the tree; a crash stops the run with the crashing input saved under build-fuzz/.
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET (default 20)] [TARGET...]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
fractalis_install_packages
seconds="${1:-20}"
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(settings_file set_override command_line scene_descriptor scene_desc_copy camera_path fract_file)

FRACTALIS_BUILD="$FRACTALIS_ROOT/build-fuzz"
# Without MPI: the fuzz targets need none, and so CI also builds the host library without it here
# (tests/mpi_single_test.cpp checks that world of one process in every build).
if [ ! -f "$FRACTALIS_BUILD/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S "$FRACTALIS_ROOT" -B "$FRACTALIS_BUILD" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFRACTALIS_FUZZ=ON -DFRACTALIS_TESTS=OFF \
    -DFRACTALIS_MPI=OFF >&2
fi
cmake --build "$FRACTALIS_BUILD" -j "$(nproc 2>/dev/null || echo 2)" \
  $(printf -- '--target fuzz_%s ' "${targets[@]}") >&2

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$FRACTALIS_BUILD/crashes"
# fuzz_one TARGET: runs it for the time given; its log in the scratch folder.
fuzz_one() {
  local target="$1"
  mkdir -p "$scratch/$target"
  # -timeout: one input over 10 s is a hang; -rss_limit_mb: one over 2 GiB is a memory blow-up.
  "$FRACTALIS_BUILD/fuzz/fuzz_$target" "$scratch/$target" "$FRACTALIS_ROOT/fuzz/corpus/$target" \
    "$FRACTALIS_ROOT/fuzz/regressions/$target" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$FRACTALIS_BUILD/crashes/$target-" 2> "$scratch/$target.log"
}
# One target per core at a time (each fuzzer is one process on one core): each still runs its
# whole time, and the stage takes the time of the targets divided by the cores.
jobs="$(nproc 2>/dev/null || echo 2)"
failed=""
for ((first = 0; first < ${#targets[@]}; first += jobs)); do
  batch=("${targets[@]:first:jobs}")
  pids=()
  for target in "${batch[@]}"; do
    echo "fractalis: fuzzing $target for ${seconds} s" >&2
    fuzz_one "$target" &
    pids+=($!)
  done
  for i in "${!batch[@]}"; do
    target="${batch[$i]}"
    if ! wait "${pids[$i]}"; then
      tail -n 40 "$scratch/$target.log" >&2
      echo "fractalis: fuzz target $target failed; the input is in $FRACTALIS_BUILD/crashes/" \
           "(copy it to fuzz/regressions/$target/ with the fix)" >&2
      failed+=" $target"
    fi
    grep -E "^stat::number_of_executed_units|^Done" "$scratch/$target.log" >&2 || true
  done
done
[ -z "$failed" ] || exit 1
echo "fractalis: ${#targets[@]} fuzz targets ran ${seconds} s each without a crash" >&2
