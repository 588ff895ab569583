#!/usr/bin/env bash
# Path tracing overhead (issue 28): the path integrator's rays per second (camera, bounce and shadow
# rays, as `lancer render` counts them) beside the default accelerator's incoherent closest-hit
# throughput on the same mesh (random rays in its box, bench/accel_bench_support.hpp), one run, one
# and two threads. Target: the path integrator at >= 70% of the incoherent rate.
#   bench/path_overhead.sh [build-dir] [mesh: 10k|100k|1m]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-build}
mesh=${2:-1m}
file="$here/data/bracket_$mesh.msh"
[[ -f $file ]] || gmsh -2 "$here/geo/bracket_$mesh.geo" -o "$file" > /dev/null
echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2) x $(nproc); load: $(cut -d' ' -f1-3 /proc/loadavg)"
for threads in 1 2; do
  accel=$(LANCER_BENCH_MESHES=$mesh "$build/bench/kd_tree_bench" \
    --benchmark_filter="trace/bvh/$mesh/incoherent/threads:$threads\$" 2>/dev/null |
    awk '/_median/ {for (i = 1; i <= NF; ++i) if ($i ~ /Mrays/) {sub(/Mrays_per_s=/, "", $(i)); print $(i); exit}}')
  [[ -n $accel ]] || accel=$(LANCER_BENCH_MESHES=$mesh "$build/bench/embree_compare_bench" \
    --benchmark_filter="trace/bvh/$mesh/incoherent/threads:$threads/" 2>/dev/null |
    awk '/_median/ {for (i = 1; i <= NF; ++i) if ($i ~ /rays_per_s|Mrays/) {sub(/Mrays_per_s=/, "", $(i)); print $(i); exit}}')
  path=$("$build/lancer" render "$file" --look studio --samples 16 --threads "$threads" --width 320 \
    --height 240 -o /tmp/lancer_path_overhead.png 2>&1 | sed -n 's/.*(\([0-9.]*\) Mrays\/s).*/\1/p')
  echo "threads $threads: BVH incoherent ${accel:-?} Mrays/s | path integrator (--look studio) $path Mrays/s"
done
