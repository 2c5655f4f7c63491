#!/usr/bin/env bash
# Times the start as a newcomer meets it: `fractalis list`, and the explorer's window (under
# Xvfb) on the scene browser and on --scene mandelbulb, each RUNS times cold (an empty
# XDG_CACHE_HOME and POCL_CACHE_DIR of its own: no vetted scenes, no compiled kernels, no
# pictures) and warm (caches an earlier run of the same command filled). For the explorer it
# takes two figures from its last line: when the window first showed something and when it first
# showed the scene (or the browser), plus the command's whole time (start to quit). Prints a
# Markdown table of the medians. Run it on a quiet machine: it measures wall time.
#
#   scripts/startup-time.sh [RUNS]        (default 3)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

if [ "${1:-}" = "--help" ]; then
  sed -n '2,10p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
  exit 2
fi
runs="${1:-3}"
if ! [[ "$runs" =~ ^[1-9][0-9]*$ ]]; then
  echo "startup-time: RUNS must be a whole number >= 1, got '$runs'" >&2
  exit 2
fi
fractalis="$FRACTALIS_BUILD/host/fractalis"
if [ ! -x "$fractalis" ]; then
  echo "startup-time: no $fractalis: build first (scripts/test.sh or scripts/run.sh)" >&2
  exit 2
fi
command -v xvfb-run >/dev/null || {
  echo "startup-time: xvfb-run is missing (apt-get install xvfb xauth)" >&2
  exit 2
}

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# run_once CACHE_DIR OUT_FILE ARGS...: runs fractalis with its caches in CACHE_DIR, writing
# "total_s shown_s frame_s" (the explorer's two figures, or - for list) to OUT_FILE.
run_once() {
  local cache="$1" out="$2"
  shift 2
  mkdir -p "$cache/xdg" "$cache/pocl"
  local start end line
  start="$(date +%s.%N)"
  if [ "$1" = "explore" ]; then
    line="$(XDG_CACHE_HOME="$cache/xdg" POCL_CACHE_DIR="$cache/pocl" \
      xvfb-run -a -s "-screen 0 1280x800x24" "$fractalis" "$@" 2>/dev/null | tail -n 1)"
  else
    XDG_CACHE_HOME="$cache/xdg" POCL_CACHE_DIR="$cache/pocl" "$fractalis" "$@" >/dev/null 2>&1
    line=""
  fi
  end="$(date +%s.%N)"
  local shown="-" frame="-"
  if [[ "$line" =~ showed\ something\ after\ ([0-9.]+)\ s,\ the\ first\ frame\ after\ ([0-9.]+)\ s ]]; then
    shown="${BASH_REMATCH[1]}"
    frame="${BASH_REMATCH[2]}"
  elif [ "$1" = "explore" ]; then
    echo "startup-time: fractalis $* said no first frame: '$line'" >&2
    exit 1
  fi
  echo "$(echo "$end - $start" | bc -l) $shown $frame" >>"$out"
}

row() {
  local label="$1"
  shift
  local cold="$work/cold.txt" warm="$work/warm.txt" n
  : >"$cold"
  : >"$warm"
  for n in $(seq "$runs"); do
    rm -rf "$work/cache"
    run_once "$work/cache" "$cold" "$@"  # cold: empty caches...
    run_once "$work/cache" "$warm" "$@"  # ...which this run finds filled
  done
  local c w
  printf '| %s | `fractalis %s` |' "$label" "$*"
  for f in "$cold" "$warm"; do
    c="$(cut -d' ' -f1 "$f" | median)"
    if [ "$(cut -d' ' -f2 "$f" | head -n 1)" = "-" ]; then
      printf ' %.2f s |' "$c"
    else
      w="$(cut -d' ' -f3 "$f" | median)"
      printf ' %.2f s (something %.2f s, the first frame %.2f s) |' "$c" \
        "$(cut -d' ' -f2 "$f" | median)" "$w"
    fi
  done
  echo
}

echo "start-up, median of $runs, $(nproc) cores, $("$fractalis" list 2>/dev/null | grep -cE '^[a-z0-9_]+ [0-9]+[.][0-9]+[.][0-9]+ ' || true) scenes listed"
echo
echo "| what | command | cold: whole command | warm: whole command |"
echo "| --- | --- | --- | --- |"
row "list the scenes" list
row "the explorer on the browser (and quit)" explore --frames 1
row "the explorer on a scene (and quit)" explore --frames 1 --scene mandelbulb
