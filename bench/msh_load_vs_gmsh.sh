#!/usr/bin/env bash
# Load time of a ~1M-triangle mesh: lancer's reader against gmsh's own, MSH 4.1 binary and ASCII
# (and MSH 2.2). Makes the meshes in bench/data/ from bench/geo/big_sphere.geo the first time
# (about a minute of gmsh meshing), then prints the best of several runs and the ratios.
#   usage: bench/msh_load_vs_gmsh.sh [BUILD_DIR]      (default: build; needs lancer and msh_load_bench)
# RUNS (default 5) sets the runs of each; LANCER_BENCH_DATA another folder for the meshes (msh_load_bench
# reads it too) and SPHERE_SIZE another element size for the sphere made there, e.g. a quick check on
# about 12K triangles: SPHERE_SIZE=0.054 LANCER_BENCH_DATA=bench/data/small bench/msh_load_vs_gmsh.sh
# gmsh is timed with `gmsh FILE -parse_and_exit -v 0`, the cheapest command that reads a whole
# mesh file; its start-up time is measured on an empty .geo and shown separately. lancer is timed by
# `lancer info --json` (loadSeconds: one cold-process load, mmap included; wall) and by the
# msh_load_bench Google Benchmark (CPU time per load, warm process). Wall and CPU (user + sys) times
# are both shown: on a shared machine the CPU times are the steadier comparison.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
runs=${RUNS:-5}
if ! command -v gmsh >/dev/null; then
  echo "msh_load_vs_gmsh: gmsh is not installed; skipping (apt-get install gmsh)"
  exit 0
fi
command -v /usr/bin/time >/dev/null || { echo "msh_load_vs_gmsh: needs /usr/bin/time (apt-get install time)" >&2; exit 1; }
for tool in "$build/lancer" "$build/bench/msh_load_bench"; do
  [[ -x $tool ]] || { echo "msh_load_vs_gmsh: $tool is missing: cmake --build $build" >&2; exit 1; }
done

data=${LANCER_BENCH_DATA:-bench/data}
mkdir -p "$data"
base=$data/big_sphere_v41_bin.msh
if [[ ! -f $base ]]; then
  echo "making $base (about a minute)..."
  gmsh bench/geo/big_sphere.geo -2 ${SPHERE_SIZE:+-setnumber size "$SPHERE_SIZE"} -format msh41 -bin -o "$base" >/dev/null
fi
convert() {  # convert FORMAT BINARY OUTPUT: re-save the same mesh with gmsh
  [[ -f $3 ]] || gmsh "$base" -save -format "$1" -setnumber Mesh.Binary "$2" -o "$3" >/dev/null
}
convert msh41 0 "$data/big_sphere_v41_ascii.msh"
convert msh22 1 "$data/big_sphere_v22_bin.msh"
convert msh22 0 "$data/big_sphere_v22_ascii.msh"

# best_of COMMAND...: the shortest wall time and the smallest CPU time (user + sys) of $runs runs, in
# seconds. On a busy machine the CPU time is the steadier figure: wall time includes waiting for a core.
best_of() {
  local best_wall= best_cpu= log
  log=$(mktemp)
  for ((i = 0; i < runs; ++i)); do
    /usr/bin/time -f "%e %U %S" -o "$log" "$@" >/dev/null 2>&1
    read -r wall user sys <"$log"
    best_wall=$(awk -v t="$wall" -v b="$best_wall" 'BEGIN { print (b == "" || t < b) ? t : b }')
    best_cpu=$(awk -v t="$user" -v s="$sys" -v b="$best_cpu" 'BEGIN { c = t + s; print (b == "" || c < b) ? c : b }')
  done
  rm -f "$log"
  echo "$best_wall $best_cpu"
}
lancer_load() {  # best loadSeconds (wall, one cold-process load, mmap included) of $runs `lancer info --json`
  local best=
  for ((i = 0; i < runs; ++i)); do
    local t
    t=$("$build/lancer" info --json "$1" | sed -n 's/.*"loadSeconds": \([0-9.e-]*\).*/\1/p')
    best=$(awk -v t="$t" -v best="$best" 'BEGIN { print (best == "" || t < best) ? t : best }')
  done
  echo "$best"
}

# lancer's CPU time per load: the Google Benchmark's cpu_time (warm process, same reader code).
csv=$(mktemp)
empty=$(mktemp --suffix=.geo)
trap 'rm -f "$empty" "$csv"' EXIT
LANCER_BENCH_DATA=$data "$build/bench/msh_load_bench" --benchmark_out="$csv" --benchmark_out_format=csv >/dev/null 2>&1
lancer_cpu() {  # lancer_cpu v41_binary: seconds
  awk -F, -v name="\"loadMsh/$1/min_time:2.000\"" '$1 == name { print $4 / 1000 }' "$csv"
}

read -r startup_wall startup_cpu < <(best_of gmsh "$empty" -parse_and_exit -v 0)
faces=$("$build/lancer" info --json "$base" | sed -n 's/.*"total": \([0-9]*\).*/\1/p')
echo "mesh: $faces triangles ($base and re-saved copies); best of $runs runs; load average $(cut -d' ' -f1 /proc/loadavg)"
printf "gmsh start-up alone (empty .geo): %.3f s wall, %.3f s CPU\n\n" "$startup_wall" "$startup_cpu"
printf "%-12s %-6s %5s | %8s %8s | %9s %9s | %10s %10s %12s\n" format file size "gmsh_wall" "gmsh_cpu" \
  "lancer_wall" "lancer_cpu" "ratio_wall" "ratio_cpu" "ratio_cpu-su"
for spec in "v41_bin v41_binary MSH4.1-binary" "v41_ascii v41_ascii MSH4.1-ASCII" \
            "v22_bin v22_binary MSH2.2-binary" "v22_ascii v22_ascii MSH2.2-ASCII"; do
  read -r suffix bench label <<<"$spec"
  path=$data/big_sphere_$suffix.msh
  read -r gw gc < <(best_of gmsh "$path" -parse_and_exit -v 0)
  lw=$(lancer_load "$path")
  lc=$(lancer_cpu "$bench")
  size=$(du -h "$path" | cut -f1)
  # ratio_cpu-su: gmsh's CPU time less its start-up, i.e. its reading alone, against lancer's.
  awk -v f="$label" -v s="$size" -v gw="$gw" -v gc="$gc" -v lw="$lw" -v lc="$lc" -v su="$startup_cpu" \
    'BEGIN { printf "%-19s %5s | %8.3f %8.3f | %11.4f %10.4f | %9.1fx %9.1fx %11.1fx\n", f, s, gw, gc, lw, lc, gw / lw, gc / lc, (gc - su) / lc }'
done
echo
echo "steady state (Google Benchmark, warm process; bytes_per_face is the Mesh's memory):"
awk -F, '$1 == "name" { for (i = 1; i <= NF; ++i) { gsub(/"/, "", $i); column[$i] = i }; next }
  $1 ~ /loadMsh/ { gsub(/"/, "", $1)
    printf "  %-36s %8.1f ms wall %8.1f ms CPU  %5.1f bytes per face\n", $1, $3, $4, $column["bytes_per_face"] }' "$csv"
