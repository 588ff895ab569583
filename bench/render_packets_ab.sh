#!/usr/bin/env bash
# The renderer's packets measured on the examples: the same binary with packets off
# (LANCER_SINGLE_RAYS=1) and on, alternated, user CPU seconds of whole `--threads 1` runs; with an
# older binary as the third argument, also its summary line's trace time and rays/s against this
# one's, 1 and 2 threads (compare the times: since ec70088 a shadow ray through glass counts as one
# ray, not one per face crossed). Images are compared byte for byte at each step.
#   bench/render_packets_ab.sh [build-dir] [rounds] [old-binary]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
rounds=${2:-5}
old=${3:-}
lancer="$build/lancer"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
TIMEFORMAT=%U
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for scene in demo glass_and_mirror; do
  for ((i = 0; i < rounds; ++i)); do
    single=$( { time LANCER_SINGLE_RAYS=1 "$lancer" render "$here/examples/$scene.toml" -o "$work/single.png" --threads 1 2>/dev/null; } 2>&1 )
    packets=$( { time "$lancer" render "$here/examples/$scene.toml" -o "$work/packets.png" --threads 1 2>/dev/null; } 2>&1 )
    echo "$scene cpu-seconds single $single packets $packets"
  done
  cmp -s "$work/single.png" "$work/packets.png" && echo "$scene: identical" || echo "$scene: IMAGES DIFFER"
  if [[ -n "$old" ]]; then
    for threads in 1 2; do
      for ((i = 0; i < rounds; ++i)); do
        a=$("$old" render "$here/examples/$scene.toml" -o "$work/old.png" --threads $threads 2>&1 | grep -o 'trace [0-9.]* s ([0-9.]* Mrays/s')
        b=$("$lancer" render "$here/examples/$scene.toml" -o "$work/new.png" --threads $threads 2>&1 | grep -o 'trace [0-9.]* s ([0-9.]* Mrays/s')
        echo "$scene threads $threads old $a new $b"
      done
      cmp -s "$work/old.png" "$work/new.png" && echo "$scene: identical to the old binary's" || echo "$scene: DIFFERS from the old binary's"
    done
  fi
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
