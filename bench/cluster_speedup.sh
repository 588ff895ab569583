#!/usr/bin/env bash
# Speed-up of `mpirun -n N lancer` against one process: a 36-frame turntable (400x300) and a large
# still (2400x1800 PNG, streamed), each rank with --threads 1 (so N ranks do N threads' work), and the
# CPU time of a rank that has nothing to do (it must sleep, not spin, while it waits).
# Usage: bench/cluster_speedup.sh [LANCER] [RANKS...]   (from the repository root; default ranks: 2)
# REPEATS (default 3) runs of each, alternating; the shortest wall time of each counts, since the
# machine is shared. CPU is user + system seconds of all processes of the run. Needs a lancer built
# with MPI and Open MPI's mpirun.
set -euo pipefail
lancer=${1:-build/lancer}
shift || true
ranks=("${@:-2}")
repeats=${REPEATS:-3}
work=$(mktemp -d /tmp/lancer-cluster-bench-XXXXXX)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # CI and containers run as root
mpirun=(mpirun --oversubscribe --bind-to none)

timed() {  # key, command...: appends "wall cpu" of the run to $work/key
  local key=$1
  shift
  /usr/bin/time -f "%e %U %S" -o "$work/time" "$@" >/dev/null 2>&1
  awk '{ printf "%s %.2f\n", $1, $2 + $3 }' "$work/time" >>"$work/$key"
}
best() { sort -n "$work/$1" | head -n 1; }  # the run with the shortest wall time

bench() {  # label, output extension, lancer arguments...
  local label=$1 ext=$2
  shift 2
  rm -f "$work"/t-*
  for ((r = 0; r < repeats; ++r)); do
    timed t-1 "$lancer" "$@" --threads 1 -q -o "$work/one.$ext"
    for n in "${ranks[@]}"; do
      timed "t-$n" "${mpirun[@]}" -n "$n" "$lancer" "$@" --threads 1 -q -o "$work/many.$ext"
      cmp -s "$work/one.$ext" "$work/many.$ext" || { echo "cluster_speedup: $n ranks wrote different bytes" >&2; exit 1; }
    done
  done
  read -r one onecpu <<<"$(best t-1)"
  printf "| %s | 1 process | %.2f s | %.2f s | 1.00 |\n" "$label" "$one" "$onecpu"
  for n in "${ranks[@]}"; do
    read -r many manycpu <<<"$(best "t-$n")"
    printf "| %s | %d ranks | %.2f s | %.2f s | %.2f (speed-up %.2f) |\n" "$label" "$n" "$many" "$manycpu" \
      "$(echo "$many / $one" | bc -l)" "$(echo "$one / $many" | bc -l)"
  done
}

echo "lancer cluster speed-up, $(nproc) cores, best of $repeats, $(date -u +%Y-%m-%dT%H:%MZ), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| job (--threads 1 per rank) | processes | wall | CPU | wall / one process |"
echo "|---|---|---|---|---|"
bench "animate demo.toml, 36 frames 400x300 GIF" gif animate examples/demo.toml --frames 36 --width 400 --height 300
bench "render demo.toml, 2400x1800 PNG" png render examples/demo.toml --width 2400 --height 1800

# Three ranks, two frames: rank 2 gets no frame and waits for the others from start to end.
"${mpirun[@]}" -n 3 sh -c "exec /usr/bin/time -f \"rank \$OMPI_COMM_WORLD_RANK: cpu %U s user + %S s system in %e s\" \
  -o '$work/idle.'\$OMPI_COMM_WORLD_RANK '$lancer' animate examples/demo.toml --frames 2 --width 400 --height 300 \
  --threads 1 -q -o '$work/idle.gif'"
cat "$work"/idle.[0-9]*
echo "(load $(cut -d' ' -f1-3 /proc/loadavg) at the end)"
