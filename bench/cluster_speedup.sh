#!/usr/bin/env bash
# Speed-up of `mpirun -n N lancer` against one process: a 36-frame turntable (400x300) and a large
# still (2400x1800 PNG, streamed), each rank with --threads 1 (so N ranks do N threads' work), and the
# CPU time of a rank that has nothing to do (it must sleep, not spin, while it waits).
# Usage: bench/cluster_speedup.sh [LANCER] [RANKS...]   (from the repository root; default ranks: 2)
# Prints wall-clock seconds and the ratio to one process; all in the same run, since the machine is
# shared. Needs a lancer built with MPI and Open MPI's mpirun.
set -euo pipefail
lancer=${1:-build/lancer}
shift || true
ranks=("${@:-2}")
work=$(mktemp -d /tmp/lancer-cluster-bench-XXXXXX)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # CI and containers run as root
mpirun=(mpirun --oversubscribe --bind-to none)

wall() {  # command...: prints its wall-clock seconds
  /usr/bin/time -f "%e" -o "$work/time" "$@" >/dev/null 2>&1
  cat "$work/time"
}

bench() {  # label, output, lancer arguments...
  local label=$1 output=$2
  shift 2
  local one
  one=$(wall "$lancer" "$@" --threads 1 -q -o "$work/one.$output")
  printf "%-34s 1 process  --threads 1: %7.2f s\n" "$label" "$one"
  for n in "${ranks[@]}"; do
    local many
    many=$(wall "${mpirun[@]}" -n "$n" "$lancer" "$@" --threads 1 -q -o "$work/many.$output")
    cmp -s "$work/one.$output" "$work/many.$output" || { echo "cluster_speedup: $n ranks wrote different bytes" >&2; exit 1; }
    printf "%-34s %2d ranks  --threads 1: %7.2f s  = %.2fx the time, speed-up %.2f (same bytes)\n" "$label" "$n" \
      "$many" "$(echo "$many / $one" | bc -l)" "$(echo "$one / $many" | bc -l)"
  done
}

echo "lancer cluster speed-up, $(nproc) cores, $(date -u +%Y-%m-%dT%H:%MZ)"
bench "animate demo.toml 36 frames 400x300" gif animate examples/demo.toml --frames 36 --width 400 --height 300
bench "render demo.toml 2400x1800 PNG" png render examples/demo.toml --width 2400 --height 1800

# Three ranks, two frames: rank 2 gets no frame and waits for the others from start to end.
"${mpirun[@]}" -n 3 sh -c "exec /usr/bin/time -f \"rank \$OMPI_COMM_WORLD_RANK: cpu %U s user + %S s system in %e s\" \
  '$lancer' animate examples/demo.toml --frames 2 --width 400 --height 300 --threads 1 -q -o '$work/idle.gif'" 2>&1 |
  sort
