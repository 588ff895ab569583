#!/usr/bin/env bash
# The build-once saving of `lancer animate`: one animation of N frames against N separate
# `lancer render` runs of the same views (each run loads the meshes and builds the kd-tree again).
# Usage: bench/animation_vs_renders.sh [LANCER] [FRAMES] [THREADS]   (from the repository root;
# KEEP=1 keeps the work folder). Views: examples/demo.toml at 400x300, the camera turned about the
# vertical axis through the centre of the scene's bounds, (0, 0.9, 0), as `lancer animate` does.
# Prints wall-clock and CPU seconds (user + system): CPU time is the steadier figure on a busy machine.
set -euo pipefail
lancer=${1:-build/lancer}
frames=${2:-36}
threads=${3:-2}
work=$(mktemp -d /tmp/lancer-anim-bench-XXXXXX)
trap '[[ -n "${KEEP:-}" ]] || rm -rf "$work"' EXIT
root=$(pwd)

# One scene file per frame: demo.toml with the camera position turned by 360 k / N degrees about y.
for ((k = 0; k < frames; ++k)); do
  position=$(awk -v k="$k" -v n="$frames" 'BEGIN { a = 2 * atan2(0, -1) * k / n; x = 4.2; z = 5.6;
    printf "[%.17g, 3.2, %.17g]", x * cos(a) + z * sin(a), -x * sin(a) + z * cos(a) }')
  sed -e "s|^position = \[4.2, 3.2, 5.6\]|position = $position|" \
      -e "s|file = \"meshes/|file = \"$root/examples/meshes/|" examples/demo.toml >"$work/view_$k.toml"
done

common="--width 400 --height 300 --threads $threads -q"
measure() {  # label, command: prints wall and CPU seconds, in total and per frame
  /usr/bin/time -f "%e %U %S" -o "$work/time" bash -c "$2" >/dev/null
  read -r wall user sys <"$work/time"
  awk -v l="$1" -v w="$wall" -v c="$(echo "$user + $sys" | bc)" -v n="$frames" \
    'BEGIN { printf "%-28s wall %6.2f s (%.3f s/frame)   cpu %6.2f s (%.3f s/frame)\n", l, w, w / n, c, c / n }'
}
echo "examples/demo.toml, $frames frames, 400x300, $threads threads"
measure "animate -> GIF" "'$lancer' animate examples/demo.toml -o '$work/turntable.gif' --frames $frames --fps 12 $common"
measure "animate -> numbered PNGs" "'$lancer' animate examples/demo.toml -o '$work/frame_%04d.png' --frames $frames $common"
measure "$frames x render -> PNG" "for ((k = 0; k < $frames; ++k)); do '$lancer' render '$work/view_'\$k.toml \
  -o '$work/render_'\$k.png $common || exit 1; done"
echo "GIF size: $(stat -c %s "$work/turntable.gif") bytes"
