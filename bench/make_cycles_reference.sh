#!/usr/bin/env bash
# Makes the committed Cycles reference of tests/render/cycles_reference_test.cpp:
# tests/data/render/cycles/cycles_bracket.exr, Blender Cycles' render of cycles_bracket.toml at
# 16384 samples per pixel (bench/cycles_scene.py: lancer's units, no denoising, linear float EXR).
# Needs Blender (Debian's blender 3.4) and gmsh; lancer's build and tests never do.
#   bench/make_cycles_reference.sh            (about 2 minutes on 2 threads)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
scene=$root/tests/data/render/cycles/cycles_bracket.toml
blender -b --factory-startup --python "$root/bench/cycles_scene.py" -- "$scene" \
  -o "$root/tests/data/render/cycles/cycles_bracket.exr" --samples 16384 --seed 1 --threads 2 |
  grep cycles_scene.py
