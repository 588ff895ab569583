#!/usr/bin/env bash
# Results over time (docs/results.md), two measurements; run under the build lock, each a few minutes:
#   bench/result_steps_bench.sh read BUILD [N=500] [STEPS=50]
#     reading a file of STEPS displacement steps on a 2 N^2-triangle plate against the ideal one pass:
#     the mesh alone + STEPS times (mesh and one step - mesh alone); `lancer info`'s load time, best of 3.
#   bench/result_steps_bench.sh animate BUILD [N=707] [STEPS=5] [THREADS=2]
#     `lancer animate --over steps` of the plate warped by the steps, 1280x720, 4 samples: the frames'
#     time and the share the per-step scene and accelerator rebuilds take (the summary's last line).
#   bench/result_steps_bench.sh memory BUILD [N=707] [STEPS=50] [THREADS=2]
#     peak RSS (/usr/bin/time) of that animation over STEPS steps against the issue's budget: a still
#     of one step plus the mesh plus two steps. The file's steps exceed 64 MB, so they stay in it.
set -euo pipefail
mode=${1:?read or animate}
build=$(realpath "${2:?build folder}")
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

load_seconds() {  # best of 3 `lancer info` load times, in seconds
  local best=""
  for _ in 1 2 3; do
    local ms
    ms=$("$build/lancer" info "$1" | awk '/^load time:/ {print $3}')
    best=$(awk -v a="$ms" -v b="${best:-1e30}" 'BEGIN {print (a < b ? a : b)}')
  done
  echo "$best"
}

if [[ $mode == read ]]; then
  n=${3:-500}; steps=${4:-50}
  /usr/bin/python3 "$here/make_result_steps.py" "$work/plate" "$n" "$steps"
  mesh=$(load_seconds "$work/plate_mesh.msh")
  one=$(load_seconds "$work/plate_1step.msh")
  all=$(load_seconds "$work/plate_${steps}steps.msh")
  awk -v n="$n" -v s="$steps" -v m="$mesh" -v o="$one" -v a="$all" 'BEGIN {
    ideal = m + s * (o - m)
    printf "plate %d triangles, %d steps: mesh %.1f ms, mesh + 1 step %.1f ms, %d steps %.1f ms; ideal one pass %.1f ms; ratio %.2f (target <= 1.5)\n",
      2 * n * n, s, m, o, s, a, ideal, a / ideal }'
  ls -la "$work"/*.msh | awk '{print $5, $9}'
elif [[ $mode == animate ]]; then
  n=${3:-707}; steps=${4:-5}; threads=${5:-2}
  /usr/bin/python3 "$here/make_result_steps.py" "$work/plate" "$n" "$steps"
  /usr/bin/time -f "peak RSS %M KB, wall %e s" "$build/lancer" animate "$work/plate_${steps}steps.msh" --over steps \
    --warp displacement:20 --color-by displacement --width 1280 --height 720 --samples 4 --threads "$threads" \
    -o "$work/frame_%02d.png" 2>&1 | tr '\r' '\n' | grep -v "^  frame"
elif [[ $mode == memory ]]; then
  # Peak memory of the animation over STEPS warped steps against what it needs at least: a still of
  # the same scene (one step) plus the steps' data it holds (4 bytes per node and component).
  n=${3:-707}; steps=${4:-50}; threads=${5:-2}
  /usr/bin/python3 "$here/make_result_steps.py" "$work/plate" "$n" "$steps"
  rm -f "$work/plate_mesh.msh"
  peak() { /usr/bin/time -f "%M" "$@" 2>&1 >/dev/null | tail -1; }
  common=(--warp displacement:20 --color-by displacement --width 1280 --height 720 --samples 4 --threads "$threads" -q)
  still=$(peak "$build/lancer" render "$work/plate_1step.msh" "${common[@]}" -o "$work/still.png")
  anim=$(peak "$build/lancer" animate "$work/plate_${steps}steps.msh" --over steps "${common[@]}" -o "$work/frame_%02d.png")
  nodes=$(( (n + 1) * (n + 1) ))
  # The issue's budget: what the still needs, plus the mesh the frames are built from (the Mesh's
  # arrays: 25 bytes a face, 12 a node, and 1 a node of lookup for reading stored steps back: the
  # plate's node tags are 1..N) plus two steps (4 bytes per node and component).
  awk -v n="$n" -v s="$steps" -v st="$still" -v an="$anim" -v nodes="$nodes" 'BEGIN {
    step = nodes * 3 * 4 / 1024; faces = 2 * n * n; mesh = (faces * 25 + nodes * 13) / 1024
    budget = st + mesh + 2 * step
    printf "plate %d triangles, %d nodes, %d steps (%.0f MB each as floats, %.0f MB all): still (1 step) %.0f MB peak RSS; animation %.0f MB; budget (still + mesh %.0f MB + 2 steps) %.0f MB: %s\n",
      faces, nodes, s, step / 1024, s * step / 1024, st / 1024, an / 1024, mesh / 1024, budget / 1024,
      an <= budget ? "within" : "OVER" }'
else
  echo "usage: $0 read|animate|memory BUILD [...]" >&2
  exit 2
fi
