#!/usr/bin/env bash
# Regenerates the optics test meshes (tests/data/optics/*.msh) and the example scene's meshes
# (examples/meshes/glass_*.msh) from their .geo files with the real gmsh. Commit the results.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v gmsh >/dev/null || { echo "make_optics_fixtures.sh: gmsh is not installed" >&2; exit 1; }
for geo in tests/data/optics/*.geo examples/meshes/glass_*.geo; do
  [[ -e $geo ]] || continue
  gmsh -2 "$geo" -format msh41 -o "${geo%.geo}.msh" > /dev/null
  echo "wrote ${geo%.geo}.msh"
done
