#!/usr/bin/env bash
# Remakes the README's pictures (docs/images) with build/lancer, each by the command its caption
# gives, so that the pictures show what those commands write today (sRGB PNGs since docs/output.md's
# default). Run after scripts/setup.sh; takes a minute on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
lancer=build/lancer
out=docs/images
"$lancer" render examples/demo.toml -o "$out/demo.png" --quiet
"$lancer" render examples/meshes/bracket.msh --samples 4 --width 640 --height 480 -o "$out/quick_look.png" --quiet
"$lancer" render examples/glass_and_mirror.toml -o "$out/glass_and_mirror.png" --quiet
"$lancer" render examples/cut_multimaterial.toml -o "$out/cut_multimaterial.png" --quiet
"$lancer" render examples/field.toml -o "$out/field.png" --quiet
"$lancer" animate examples/demo.toml -o "$out/turntable.gif" --frames 36 --fps 12 --width 400 --height 300 --quiet
"$lancer" render tests/data/results/cantilever.msh --warp displacement:1 --color-by stress:von_mises --step 3 \
  --undeformed edges --width 480 --height 270 --samples 4 -o "$out/results_warp.png" --quiet
# The three looks side by side (docs/lighting.md#looks): the same part, one option apart.
for look in studio sky sun; do
  "$lancer" render examples/meshes/bracket.msh --look "$look" --denoise --width 320 --height 240 \
    -o "$out/look_preset_$look.png" --quiet
done
# Results made by gmsh (scripts/make_result_examples.py writes examples/results/*.msh): a beam bent by
# its displacement, coloured by von Mises stress with isolines and a legend; the same over its time
# steps, labelled; arrows on a flow.
"$lancer" render examples/results/beam.toml -o "$out/results_beam.png" --quiet
"$lancer" animate examples/results/beam.toml --over steps --frames 20 --width 480 --height 270 \
  -o "$out/results_beam.gif" --quiet
"$lancer" render examples/results/flow.toml -o "$out/results_flow.png" --quiet
# docs/volume.md's arrows through the volume: a grid of the capacitor's field, 0.8 cells long by
# default, coloured by magnitude on a log scale (the field spans two decades), with its legend.
"$lancer" render tests/data/volume/capacitor.msh --arrows e --arrow-grid 10,10,8 --legend right \
  --log --range 0.05:8 --width 480 --height 360 --samples 4 -o "$out/volume_arrows.png" --quiet
