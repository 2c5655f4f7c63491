#!/usr/bin/env bash
# Renders each importable Mandelbulber2 example in Mandelbulber2 itself (Debian's mandelbulber2,
# headless, its z-buffer pass) and in Fractalis (the same file through --preset, an OpenEXR with
# depth and hit mask), at the same size, and compares the surfaces (tests/mb2_compare.cpp: hit
# mask mismatch with one pixel of tolerance, depth difference in pixel footprints). Both render
# with the effects that do not move the surface switched off, at the file's own detail level
# (Fractalis's hit threshold 1/detail_level), on every core; the times are each program's
# rendering alone, at its steady pace: Mandelbulber2's wall time less that of an 8x8 render of the
# same file (its start-up; a render there takes seconds), Fractalis's median frame of `bench`
# (the whole frame: precision probe, cone pass, march, shading, read-back; kernel built, warm).
# A single `render` in a fresh process is timed too (the median of three, extra columns): its
# first frame runs about a third slower than warm ones, mostly memory touched for the first time
# (docs/mandelbulber2.md, "Speed against Mandelbulber2").
#
# usage: scripts/compare-mandelbulber2.sh [--examples DIR] [--width PX] [--limit N] [--out DIR]
#                                         [--match TEXT] [--require PERCENT] [--build DIR]
#                                         [--no-build] [--counts]
#   --examples  the .fract files (default: mandelbulber2-data's examples)
#   --width     image width; the height keeps each file's aspect (default 160)
#   --limit     compare at most N importable files (default: all)
#   --match     only files whose path contains TEXT
#   --out       where renders, logs and results.tsv go (default: build/mb2-compare)
#   --require   exit 1 unless at least PERCENT of the files compared are within 3% mismatch and
#               5 footprints (the CTest entry, label mandelbulber2, runs a few files so)
#   --build     the build folder to take fractalis and mb2_compare from (default: build/)
#   --no-build  install nothing and build nothing (CTest runs it from a built tree)
#   --counts    also add where the DE evaluations went (bench's counting run, untimed) to the
#               summary, by family: per pixel, the march's lane evaluations made and the share
#               of its lanes busy, all stages' (results.tsv has them always)
# Prints one line per file and a summary; results.tsv has the table (docs/mandelbulber2.md).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

examples=/usr/share/mandelbulber2/examples
width=160
limit=0
match=""
out=""
require=""
build=1
counts=0
while [ $# -gt 0 ]; do
  case "$1" in
    --examples) examples="$2"; shift 2 ;;
    --width) width="$2"; shift 2 ;;
    --limit) limit="$2"; shift 2 ;;
    --match) match="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --require) require="$2"; shift 2 ;;
    --build) FRACTALIS_BUILD="$2"; shift 2 ;;
    --no-build) build=0; shift ;;
    --counts) counts=1; shift ;;
    *) echo "compare-mandelbulber2: unknown argument '$1'" >&2; exit 2 ;;
  esac
done

[ -n "$out" ] || out="$FRACTALIS_BUILD/mb2-compare"
if [ "$build" -eq 1 ]; then
  fractalis_install_packages
  fractalis_build
fi
command -v mandelbulber2 >/dev/null || { echo "compare-mandelbulber2: mandelbulber2 is not installed" >&2; exit 1; }
fractalis="$FRACTALIS_BUILD/host/fractalis"
compare="$FRACTALIS_BUILD/tests/mb2_compare"
[ -x "$compare" ] || { echo "compare-mandelbulber2: $compare was not built (needs OpenEXR)" >&2; exit 1; }
[ -d "$examples" ] || { echo "compare-mandelbulber2: no folder $examples" >&2; exit 2; }

mkdir -p "$out/mb" "$out/fr" "$out/presets" "$out/log"
results="$out/results.tsv"
printf 'file\tformulas\tsize\tmismatch_percent\tmedian_footprints\tp90_footprints\tmb2_s\tfractalis_s\tspeed_ratio\tmarch_made\tmarch_busy_percent\tnormals_made\tcolour_made\ttotal_made\tfractalis_render_s\trender_speed_ratio\n' >"$results"

# Mandelbulber2's switches for a plain surface: no effect that blurs, jitters or costs time
# without moving the surface. Booleans are 1/0 on its command line.
mb2_plain='zbuffer_enabled=1#antialiasing_enabled=0#DOF_enabled=0#DOF_monte_carlo=0'
mb2_plain+='#ambient_occlusion_enabled=0#shadows_enabled=0#raytraced_reflections=0'
mb2_plain+='#volumetric_fog_enabled=0#iteration_fog_enable=0#glow_enabled=0#basic_fog_enabled=0'
mb2_plain+='#fake_lights_enabled=0#main_light_volumetric_enabled=0#hdr_blur_enabled=0'
mb2_plain+='#aux_light_volumetric_enabled_1=0#aux_light_volumetric_enabled_2=0'
mb2_plain+='#aux_light_volumetric_enabled_3=0#aux_light_volumetric_enabled_4=0#env_mapping_enable=0'
mb2_plain+='#mat1_transparency_of_surface=0'
fractalis_plain=(--set render.effects.shadows=false --set render.effects.ao=false
  --set render.effects.glow=false --set render.effects.fog=false
  --set render.effects.reflections=false --set render.effects.dof=false --samples 1)

# The value of a [main_parameters] key of a .fract file, decimal comma made a dot; $2 if absent.
fract_value() {
  local v
  v=$(sed -n "/^\[main_parameters\]/,/^\[/{s/^$2 \(.*\);\s*$/\1/p}" "$1" | head -n 1 | tr ',' '.')
  echo "${v:-$3}"
}

now() { date +%s.%N; }

compared=0
declare -A seen
while IFS= read -r -d '' file; do
  [ -n "$match" ] && [[ "$file" != *"$match"* ]] && continue
  [ "$limit" -gt 0 ] && [ "$compared" -ge "$limit" ] && break
  name=$(basename "$file" .fract)
  id=$(echo "$name" | tr 'A-Z' 'a-z' | tr -c 'a-z0-9\n' '_')
  # Two collections hold a mandelbox22_anim: a second file of a name gets a suffix (and its own
  # preset folder, since import never replaces a preset with other contents).
  if [ -n "${seen[$id]:-}" ]; then
    seen[$id]=$((seen[$id] + 1))
    id="${id}_${seen[$id]}"
  else
    seen[$id]=1
  fi
  mkdir -p "$out/presets/$id"
  if ! "$fractalis" import "$file" --out "$out/presets/$id" --force >"$out/log/$id.import" 2>&1; then
    continue
  fi
  compared=$((compared + 1))
  iw=$(fract_value "$file" image_width 800)
  ih=$(fract_value "$file" image_height 600)
  fov=$(fract_value "$file" fov 1)
  height=$(( (width * ih + iw / 2) / iw ))
  [ "$height" -ge 8 ] || height=8
  preset=$(sed -n 's/^wrote \(.*\) (preset .*/\1/p' "$out/log/$id.import")
  formulas=$(sed -n 's/^f[1-9] = "\([a-z0-9_]*\)"$/\1/p' "$preset" | grep -v '^none$' | sort -u | paste -sd+ -)

  # Mandelbulber2: the view, then an 8x8 render for its start-up time.
  t0=$(now)
  mandelbulber2 -n -r "${width}x${height}" -f png -o "$out/mb/$id" -O "$mb2_plain" "$file" \
    >"$out/log/$id.mb2" 2>&1 || { echo "$name: mandelbulber2 failed (log: $out/log/$id.mb2)"; continue; }
  t1=$(now)
  mandelbulber2 -n -r 8x8 -f png -o "$out/mb/${id}_startup" -O "$mb2_plain" "$file" \
    >/dev/null 2>&1 || true
  t2=$(now)
  mb2_s=$(echo "$t0 $t1 $t2" | awk '{ s = ($2 - $1) - ($3 - $2); if (s < 0.001) s = 0.001; printf "%.3f", s }')

  # Fractalis: once to build the kernel (and the picture compared), then its warm frames timed by
  # `bench` (median of five), with where their DE evaluations went; then three single renders,
  # each in a fresh process, the median timed (one render's time varies by a fifth).
  "$fractalis" render --preset "$file" --size "${width}x${height}" "${fractalis_plain[@]}" \
    --out "$out/fr/$id.exr" >"$out/log/$id.fractalis" 2>&1 || { echo "$name: fractalis failed"; continue; }
  "$fractalis" bench --preset "$file" --size "${width}x${height}" "${fractalis_plain[@]}" \
    --frames 5 --runs 1 --duration 0 >"$out/log/$id.bench" 2>&1 || { echo "$name: fractalis bench failed"; continue; }
  fr_ms=$(sed -n 's/^median \([0-9.]*\) ms.*/\1/p' "$out/log/$id.bench" | head -n 1)
  [ -n "$fr_ms" ] || { echo "$name: fractalis bench reported no median (log: $out/log/$id.bench)"; continue; }
  fr_s=$(awk -v ms="$fr_ms" 'BEGIN { s = ms / 1000; if (s < 0.001) s = 0.001; printf "%.4f", s }')
  stages=$(awk '
    /^ *primary +march / { march = $NF; busy = $(NF - 2); sub(/%/, "", busy) }
    /^ *primary +normals / { normals = $NF }
    /^ *primary +surface colour / { colour = $NF }
    /^ *total / { total = $NF }
    END { printf "%s\t%s\t%s\t%s\t%s", march, busy, normals, colour, total }' "$out/log/$id.bench")
  for run in 1 2 3; do
    "$fractalis" render --preset "$file" --size "${width}x${height}" "${fractalis_plain[@]}" \
      --out "$out/fr/$id.exr" >"$out/log/$id.fractalis" 2>&1
    sed -n 's/.*render \([0-9.]*\) ms.*/\1/p' "$out/log/$id.fractalis" | head -n 1
  done >"$out/log/$id.fractalis_ms"
  render_ms=$(sort -g "$out/log/$id.fractalis_ms" | sed -n 2p)
  [ -n "$render_ms" ] || { echo "$name: fractalis render reported no time (log: $out/log/$id.fractalis)"; continue; }
  render_s=$(awk -v ms="$render_ms" 'BEGIN { s = ms / 1000; if (s < 0.001) s = 0.001; printf "%.3f", s }')
  metrics=$("$compare" "$out/mb/${id}_zbuffer.png" "$out/fr/$id.exr" "$fov") || { echo "$name: compare failed"; continue; }
  read -r mismatch median p90 _ _ <<<"$metrics"
  ratio=$(awk -v a="$mb2_s" -v b="$fr_s" 'BEGIN { printf "%.1f", a / b }')
  render_ratio=$(awk -v a="$mb2_s" -v b="$render_s" 'BEGIN { printf "%.1f", a / b }')
  printf '%s\t%s\t%sx%s\t%s\t%s\t%s\t%s\t%s\t%s\t%b\t%s\t%s\n' "${file#"$examples"/}" "$formulas" \
    "$width" "$height" "$mismatch" "$median" "$p90" "$mb2_s" "$fr_s" "$ratio" "$stages" "$render_s" \
    "$render_ratio" >>"$results"
  echo "$name [$formulas]: mismatch ${mismatch}%, depth ${median} footprints (p90 $p90), mandelbulber2 ${mb2_s} s, fractalis ${fr_s} s a frame (${ratio}x; one render ${render_s} s, ${render_ratio}x)"
done < <(find "$examples" -name '*.fract' -print0 | sort -z)

# The summary: files within 3% mismatch and 5 footprints; median and worst speed ratio.
n=$(($(wc -l <"$results") - 1))
if [ "$n" -le 0 ]; then
  echo "no importable file compared" >&2
  exit 1
fi
ok=$(awk -F'\t' 'NR > 1 && $4 <= 3 && $5 != "nan" && $5 <= 5 { k++ } END { print k + 0 }' "$results")
# The median and the least of results.tsv's column $1.
median_and_worst() {
  awk -F'\t' -v c="$1" 'NR > 1 { print $c }' "$results" | sort -g |
    awk '{ r[NR] = $1 } END { printf "%s %s", (NR % 2 ? r[(NR + 1) / 2] : (r[NR / 2] + r[NR / 2 + 1]) / 2), r[1] }'
}
read -r median worst <<<"$(median_and_worst 9)"
read -r render_median render_worst <<<"$(median_and_worst 16)"
echo "$n files compared: $ok within 3% mismatch and 5 footprints; speed ratio median ${median}x, worst ${worst}x (warm frames; one render in a fresh process: median ${render_median}x, worst ${render_worst}x)"
# By formula family: files, within tolerance, median speed ratio.
echo "by formulas (files, within tolerance, median speed ratio):"
awk -F'\t' 'NR > 1 { print $2 "\t" ($4 <= 3 && $5 != "nan" && $5 <= 5) "\t" $9 }' "$results" |
  sort -t$'\t' -k1,1 -k3,3g |
  awk -F'\t' '{ n[$1]++; ok[$1] += $2; r[$1, n[$1]] = $3 }
    END { for (f in n) { m = n[f]; med = (m % 2 ? r[f, (m + 1) / 2] : (r[f, m / 2] + r[f, m / 2 + 1]) / 2)
            printf "  %-32s %3d %3d %6.1fx\n", f, m, ok[f], med } }' | sort
if [ "$counts" -eq 1 ]; then
  # By family, the medians of the evaluations a pixel: the march's (and its lanes busy), all.
  echo "by formulas, DE evaluations a pixel (medians: march made, march lanes busy %, all made):"
  awk -F'\t' 'NR > 1 && $10 != "-" { print $2 "\t" $10 "\t" $11 "\t" $14 }' "$results" |
    awk -F'\t' '{ n[$1]++; for (c = 2; c <= 4; c++) v[$1, c, n[$1]] = $c }
      END { for (f in n) { m = n[f]; printf "  %-32s", f
              for (c = 2; c <= 4; c++) {
                for (i = 1; i <= m; i++) {  # insertion sort (mawk has no asort)
                  x = v[f, c, i] + 0; j = i - 1
                  while (j > 0 && s[j] > x) { s[j + 1] = s[j]; j-- }
                  s[j + 1] = x }
                printf " %8.1f", (m % 2 ? s[(m + 1) / 2] : (s[m / 2] + s[m / 2 + 1]) / 2) }
              printf "\n" } }' | sort
fi
echo "table: $results"
if [ -n "$require" ] && [ $((100 * ok)) -lt $((require * n)) ]; then
  echo "compare-mandelbulber2: $ok of $n within tolerance, fewer than $require%" >&2
  exit 1
fi
