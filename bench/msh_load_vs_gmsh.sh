#!/usr/bin/env bash
# Load time of a ~1M-triangle mesh: lancer's reader against gmsh's own, MSH 4.1 binary and ASCII
# (and MSH 2.2). Makes the meshes in bench/data/ from bench/geo/big_sphere.geo the first time
# (about a minute of gmsh meshing), then prints the best of several runs and the ratios.
#   usage: bench/msh_load_vs_gmsh.sh [BUILD_DIR]      (default: build; needs lancer and msh_load_bench)
# gmsh is timed with `gmsh FILE -parse_and_exit -v 0`, the cheapest command that reads a whole
# mesh file (it logs every node and element block); its start-up time is measured on an empty .geo
# and shown separately. lancer is timed by `lancer info --json` (loadSeconds: one cold-process load,
# mmap included) and by the msh_load_bench Google Benchmark (steady state, warm allocator).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
runs=${RUNS:-5}
if ! command -v gmsh >/dev/null; then
  echo "msh_load_vs_gmsh: gmsh is not installed; skipping (apt-get install gmsh)"
  exit 0
fi
for tool in "$build/lancer" "$build/bench/msh_load_bench"; do
  [[ -x $tool ]] || { echo "msh_load_vs_gmsh: $tool is missing: cmake --build $build" >&2; exit 1; }
done

data=bench/data
mkdir -p "$data"
base=$data/big_sphere_v41_bin.msh
if [[ ! -f $base ]]; then
  echo "making $base (about a minute)..."
  gmsh bench/geo/big_sphere.geo -2 -format msh41 -bin -o "$base" >/dev/null
fi
convert() {  # convert FORMAT BINARY OUTPUT: re-save the same mesh with gmsh
  [[ -f $3 ]] || gmsh "$base" -save -format "$1" -setnumber Mesh.Binary "$2" -o "$3" >/dev/null
}
convert msh41 0 "$data/big_sphere_v41_ascii.msh"
convert msh22 1 "$data/big_sphere_v22_bin.msh"
convert msh22 0 "$data/big_sphere_v22_ascii.msh"

now() { date +%s.%N; }
# best_of COMMAND...: the shortest wall time of $runs runs, in seconds.
best_of() {
  local best=
  for ((i = 0; i < runs; ++i)); do
    local start end
    start=$(now)
    "$@" >/dev/null 2>&1
    end=$(now)
    best=$(awk -v a="$start" -v b="$end" -v best="$best" 'BEGIN { t = b - a; print (best == "" || t < best) ? t : best }')
  done
  echo "$best"
}
lancer_load() {  # best loadSeconds of $runs `lancer info --json` runs
  local best=
  for ((i = 0; i < runs; ++i)); do
    local t
    t=$("$build/lancer" info --json "$1" | sed -n 's/.*"loadSeconds": \([0-9.e-]*\).*/\1/p')
    best=$(awk -v t="$t" -v best="$best" 'BEGIN { print (best == "" || t < best) ? t : best }')
  done
  echo "$best"
}

empty=$(mktemp --suffix=.geo)
trap 'rm -f "$empty"' EXIT
startup=$(best_of gmsh "$empty" -parse_and_exit -v 0)
faces=$("$build/lancer" info --json "$base" | sed -n 's/.*"total": \([0-9]*\).*/\1/p')
echo "mesh: $faces triangles ($base and re-saved copies); best of $runs runs"
printf "gmsh start-up alone: %.3f s\n\n" "$startup"
printf "%-24s %10s %10s %12s %12s %10s\n" file size gmsh_s "lancer_s" ratio "ratio-startup"
for file in big_sphere_v41_bin big_sphere_v41_ascii big_sphere_v22_bin big_sphere_v22_ascii; do
  path=$data/$file.msh
  g=$(best_of gmsh "$path" -parse_and_exit -v 0)
  l=$(lancer_load "$path")
  size=$(du -h "$path" | cut -f1)
  awk -v f="$file" -v s="$size" -v g="$g" -v l="$l" -v st="$startup" \
    'BEGIN { printf "%-24s %10s %10.3f %12.4f %11.1fx %11.1fx\n", f, s, g, l, g / l, (g - st) / l }'
done
echo
echo "steady state (Google Benchmark, warm process):"
"$build/bench/msh_load_bench" --benchmark_min_time=1 2>&1 | grep -E "^(Benchmark|loadMsh|-)"
