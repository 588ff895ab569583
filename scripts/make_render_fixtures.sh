#!/usr/bin/env bash
# Regenerates, with the real gmsh, the meshes of the render tests (tests/data/render) and of the
# bundled examples (examples/meshes) from their committed .geo files. Needs gmsh (apt-get install
# gmsh); lancer's build and tests do not.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v gmsh >/dev/null || { echo "make_render_fixtures: gmsh is not installed" >&2; exit 1; }
# mesh GEO_WITHOUT_EXTENSION: MSH 4.1 binary beside the .geo; a 3D mesh when the .geo defines a
# Physical Volume (gmsh then saves only the volume elements, and lancer renders their skin), else 2D.
mesh() {
  local dim=2
  grep -q '^Physical Volume' "$1.geo" && dim=3
  gmsh "$1.geo" -"$dim" -format msh41 -bin -o "$1.msh" >/dev/null
  rm -f "$1.geo_unrolled"
}
for geo in tests/data/render/*.geo; do mesh "${geo%.geo}"; done
# The terrain has no geometry, only a mesh: gmsh's Python API builds it (python3-gmsh).
/usr/bin/python3 tests/data/render/terrain.py tests/data/render/terrain.msh
for name in bracket floor sphere three_materials; do mesh "examples/meshes/$name"; done
