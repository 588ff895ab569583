#!/usr/bin/env bash
# lancer's path tracer against Blender Cycles on the same scene (bench/cycles/bracket_*.toml, rendered by
# Cycles through bench/cycles_scene.py in lancer's units), both on 2 threads, no denoising on either side
# unless said. Prints the tables of bench/RESULTS.md "Against Blender Cycles":
#  1. units: the floor in a uniform environment (kd L) and under a sun (kd I cos), both renderers;
#  2. per mesh: a Cycles reference at 4096 samples (4 x 1024 with seeds 1-4, averaged; cached in
#     bench/data/cycles/), Cycles at 64 samples timed end to end (process start to file, median of 3),
#     then lancer at increasing samples until its RMSE against the reference is at most Cycles@64's,
#     without and with --denoise; the time ratio lancer / Cycles.
# RMSE: over every pixel and R, G, B, of linear float values (EXR), no clamp (bench/exr_compare).
# Every render holds /tmp/lancer-build.lock (one render at a time, none beside a build).
#   bench/cycles_compare.sh [build-dir] [meshes]      e.g. bench/cycles_compare.sh build 10k,1m
# Needs Blender (Debian's blender 3.4) and gmsh: development tools, never lancer's.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-build}" && pwd)
meshes=${2:-10k}
lancer=$build/lancer
compare=$build/bench/exr_compare
data=$here/data/cycles
mkdir -p "$data"
lock=/tmp/lancer-build.lock

for mesh in cycles_floor ${meshes//,/ }; do
  name=$mesh
  [[ $mesh == cycles_floor ]] || name=bracket_$mesh
  if [[ ! -f $here/data/$name.msh ]]; then
    echo "making $name.msh with gmsh..." >&2
    flock $lock nice gmsh -2 "$here/geo/$name.geo" -o "$here/data/$name.msh" > "$here/data/$name.log" 2>&1
  fi
done

cycles() {  # SCENE OUT SAMPLES SEED
  flock $lock blender -b --factory-startup --python "$here/cycles_scene.py" -- "$1" -o "$2" --samples "$3" \
    --seed "$4" --threads 2 2>&1 | grep 'cycles_scene.py' >&2
}

# Wall seconds of a whole command (process start to file), holding the lock.
timed() {
  flock $lock bash -c 'start=$(date +%s.%N); "$@" > /dev/null 2>&1; printf "%.2f\n" "$(echo "$(date +%s.%N) - $start" | bc)"' _ "$@"
}

median3() { printf '%s\n' "$@" | sort -g | sed -n 2p; }

rmse() { "$compare" diff "$1" "$2" | awk '/^RMSE/ {print $2}'; }

echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2) x $(nproc); $(blender --version | head -1); lancer $(git -C "$here" rev-parse --short HEAD)"
echo
echo "## Units (64 samples each; expected floor: uniform environment kd L = 0.4 0.42 0.42, sun kd I cos = 0.3 0.36 0.42)"
for check in plane_env plane_sun; do
  cycles "$here/cycles/$check.toml" "$data/$check-cycles.exr" 64 0
  flock $lock "$lancer" render "$here/cycles/$check.toml" -o "$data/$check-lancer.exr" --samples 64 --threads 2 -q
  echo "$check: lancer $("$compare" stats "$data/$check-lancer.exr" | sed 's/.*mean/mean/')," \
    "Cycles $("$compare" stats "$data/$check-cycles.exr" | sed 's/.*mean/mean/')"
done

for mesh in ${meshes//,/ }; do
  scene=$here/cycles/bracket_$mesh.toml
  ref=$data/bracket_${mesh}_ref4096.exr
  if [[ ! -f $ref ]]; then
    for seed in 1 2 3 4; do
      part=$data/bracket_${mesh}_ref1024_seed$seed.exr
      [[ -f $part ]] || cycles "$scene" "$part" 1024 "$seed"
    done
    "$compare" average "$ref" "$data"/bracket_${mesh}_ref1024_seed{1,2,3,4}.exr > /dev/null
  fi
  echo
  echo "## bracket_$mesh ($(awk -F' = ' '/^width/ {w=$2} /^height/ {h=$2} END {print w "x" h}' "$scene"))"
  echo "reference: Cycles 4096 samples (4 x 1024, seeds 1-4); its own noise: RMSE of seed 1 against seed 2" \
    "$(rmse "$data/bracket_${mesh}_ref1024_seed1.exr" "$data/bracket_${mesh}_ref1024_seed2.exr") (1024 samples each)"
  cycles_out=$data/bracket_${mesh}_cycles64.exr
  c=()
  for run in 1 2 3; do
    c+=("$(timed blender -b --factory-startup --python "$here/cycles_scene.py" -- "$scene" -o "$cycles_out" \
      --samples 64 --seed 7 --threads 2)")
  done
  cycles_time=$(median3 "${c[@]}")
  target=$(rmse "$cycles_out" "$ref")
  echo "Cycles 64 samples: RMSE $target, ${cycles_time} s (runs: ${c[*]})"
  echo "bias check, Cycles 64 against the reference:"
  "$compare" diff "$cycles_out" "$ref" | tail -n +2
  echo "bias check, lancer 256 samples against the reference:"
  flock $lock "$lancer" render "$scene" -o "$data/bracket_${mesh}_lancer256.exr" --samples 256 --threads 2 -q
  "$compare" diff "$data/bracket_${mesh}_lancer256.exr" "$ref" | tail -n +2

  echo
  echo "| renderer | samples | time (s) | RMSE | time / Cycles@64 |"
  echo "|---|---|---|---|---|"
  echo "| Cycles | 64 | $cycles_time | $target | 1 |"
  for denoise in "" "--denoise"; do
    found=""
    for samples in 1 2 3 4 6 8 12 16 20 24 28 32 40 48 56 64 80 96 128 160 192 256; do
      out=$data/bracket_${mesh}_lancer.exr
      flock $lock "$lancer" render "$scene" -o "$out" --samples "$samples" --threads 2 -q $denoise
      error=$(rmse "$out" "$ref")
      echo "  lancer $denoise $samples samples: RMSE $error" >&2
      if (($(echo "$error <= $target" | bc -l))); then
        found=$samples
        break
      fi
    done
    if [[ -z $found ]]; then
      echo "| lancer $denoise | > 256 | - | - | - |"
      continue
    fi
    t=()
    for run in 1 2 3; do
      t+=("$(timed "$lancer" render "$scene" -o "$out" --samples "$found" --threads 2 -q $denoise)")
    done
    lancer_time=$(median3 "${t[@]}")
    echo "| lancer $denoise | $found | $lancer_time | $error | $(echo "scale=3; $lancer_time / $cycles_time" | bc) |"
  done
done
