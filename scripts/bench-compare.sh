#!/usr/bin/env bash
# Compares `fractalis bench` between another revision and this working tree, on this machine, in
# one run: builds REV in a worktree beside this one (build-compare/, ccache makes it quick after the
# first time), builds this tree, then runs the same bench command ROUNDS times for each,
# alternating, so that the machine's load drifts over both alike. Prints each round's medians and
# the ratio of the medians of medians (REV / this tree: above 1 means this tree is faster).
#
#   scripts/bench-compare.sh REV [ROUNDS] -- BENCH ARGUMENTS...
#   scripts/bench-compare.sh origin/main 3 -- --size 1366x768 --frames 10 --runs 1
#   scripts/bench-compare.sh HEAD~3 5 -- --scene mandelbulb --size 640x360 --frames 20 --runs 1
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

if [ $# -lt 1 ] || [ "$1" = "--help" ]; then
  sed -n '2,11p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
  exit 2
fi
rev="$1"
shift
rounds=3
if [ $# -gt 0 ] && [ "$1" != "--" ]; then
  rounds="$1"
  shift
fi
[ $# -gt 0 ] && [ "$1" = "--" ] && shift
if ! [[ "$rounds" =~ ^[1-9][0-9]*$ ]]; then
  echo "bench-compare: ROUNDS must be a whole number >= 1, got '$rounds'" >&2
  exit 2
fi
commit="$(git -C "$FRACTALIS_ROOT" rev-parse --verify --quiet "$rev^{commit}")" || {
  echo "bench-compare: '$rev' is not a revision of this repository" >&2
  exit 2
}

fractalis_install_packages
compare_dir="$FRACTALIS_ROOT/build-compare"
worktree="$compare_dir/src"
if [ ! -d "$worktree" ]; then
  mkdir -p "$compare_dir"
  git -C "$FRACTALIS_ROOT" worktree add --detach "$worktree" "$commit" >&2
else
  git -C "$worktree" checkout --quiet --detach "$commit"
fi
echo "bench-compare: building $rev ($commit) in $compare_dir/build" >&2
FRACTALIS_BUILD="$compare_dir/build" FRACTALIS_ROOT="$worktree" fractalis_build -DFRACTALIS_TESTS=OFF
echo "bench-compare: building this tree in $FRACTALIS_BUILD" >&2
fractalis_build

median_of() { # the "median N ms" line of a bench report
  sed -n 's/^median \([0-9.]*\) ms.*/\1/p' | head -n 1
}
base_medians=()
this_medians=()
for ((round = 1; round <= rounds; ++round)); do
  base="$("$compare_dir/build/host/fractalis" bench "$@" 2>/dev/null | median_of)"
  this="$("$FRACTALIS_BUILD/host/fractalis" bench "$@" 2>/dev/null | median_of)"
  if [ -z "$base" ] || [ -z "$this" ]; then
    echo "bench-compare: a bench run failed; run it alone to see why: fractalis bench $*" >&2
    exit 1
  fi
  printf 'round %d: %s %s ms, this tree %s ms\n' "$round" "$rev" "$base" "$this"
  base_medians+=("$base")
  this_medians+=("$this")
done
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
b="$(median "${base_medians[@]}")"
t="$(median "${this_medians[@]}")"
printf 'median of %d rounds: %s %s ms, this tree %s ms: %sx\n' "$rounds" "$rev" "$b" "$t" \
  "$(awk -v b="$b" -v t="$t" 'BEGIN {printf "%.2f", b / t}')"
