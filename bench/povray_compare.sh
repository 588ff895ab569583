#!/usr/bin/env bash
# End-to-end `lancer render` against POV-Ray 3.7 on the bench meshes: the same scene
# (camera, one point light with shadows, Phong-like material, smoothed normals, resolution and
# 4 samples per pixel) written for both by pov_scene_writer, each run file to PNG, wall times and
# the ratio printed. Skips cleanly when povray is not installed.
#   bench/povray_compare.sh [build-dir] [meshes] [WxH]    e.g. bench/povray_compare.sh build-accel 10k,1m 800x600
# Both renderers use every core. Scene files go to bench/data/pov/ (git-ignored).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-build}" && pwd)
meshes=${2:-10k,100k,1m,4m}
size=${3:-800x600}
width=${size%x*}
height=${size#*x}
if ! command -v povray > /dev/null; then
  echo "povray not installed: skipping the POV-Ray comparison"
  exit 0
fi
for tool in "$build/lancer" "$build/bench/pov_scene_writer"; do
  [[ -x $tool ]] || { echo "missing $tool: build the project first" >&2; exit 1; }
done
work="$here/data/pov"
mkdir -p "$work"
now() { date +%s.%N; }

echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2) x $(nproc); load before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "${width}x${height}, 4 samples/pixel, one point light with shadows; seconds of wall time"
echo
echo "| mesh | faces | lancer total | lancer load+build | lancer trace | POV-Ray total | POV-Ray parse | POV-Ray trace | total ratio POV/lancer | trace ratio POV/lancer |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for mesh in ${meshes//,/ }; do
  msh="$here/data/bracket_$mesh.msh"
  if [[ ! -f $msh ]]; then
    echo "making $msh with gmsh..." >&2
    gmsh -2 "$here/geo/bracket_$mesh.geo" -o "$msh" > "$here/data/bracket_$mesh.log" 2>&1
  fi
  base="$work/bracket_$mesh"
  "$build/bench/pov_scene_writer" "$msh" "$base" "$width" "$height"

  start=$(now)
  "$build/lancer" render "$base.toml" 2> "$base-lancer.log"
  lancer_total=$(echo "$(now) - $start" | bc -l)
  # "... load 0.123 s, build 0.456 s, trace 0.789 s (..."
  read -r load build_s trace faces < <(sed -nE 's/.*, ([0-9]+) faces,.*load ([0-9.]+) s, build ([0-9.]+) s, trace ([0-9.]+) s.*/\2 \3 \4 \1/p' "$base-lancer.log")

  start=$(now)
  povray "+I$base.pov" "+O$base-povray.png" +FN "+W$width" "+H$height" +A0.0 +AM1 +R2 -D +WT"$(nproc)" \
    > "$base-povray.log" 2>&1
  pov_total=$(echo "$(now) - $start" | bc -l)
  # "Parse Time:    0 hours  0 minutes  5 seconds (5.123 seconds)"
  pov_parse=$(sed -nE 's/^ *Parse Time:.*\(([0-9.]+) seconds\).*/\1/p' "$base-povray.log" | head -1)
  pov_trace=$(sed -nE 's/^ *Trace Time:.*\(([0-9.]+) seconds\).*/\1/p' "$base-povray.log" | head -1)
  printf "| %s | %s | %.2f | %.2f | %.3f | %.2f | %s | %s | %.1f | %.1f |\n" "$mesh" "$faces" "$lancer_total" \
    "$(echo "$load + $build_s" | bc -l)" "$trace" "$pov_total" "${pov_parse:--}" "${pov_trace:--}" \
    "$(echo "$pov_total / $lancer_total" | bc -l)" "$(echo "${pov_trace:-0} / $trace" | bc -l)"
done
echo
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
