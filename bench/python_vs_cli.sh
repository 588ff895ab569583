#!/usr/bin/env bash
# The Python module against the CLI on bench/data/bracket_1m_bin.msh (~1M triangles; made with gmsh
# from bench/geo/bracket_1m.geo the first time): array conversion against the file reader, and a
# render from Python against `lancer render`. Figures for the README's Python section.
#   usage: bench/python_vs_cli.sh [BUILD_DIR]     (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
mesh=bench/data/bracket_1m_bin.msh
if [[ ! -f $mesh ]]; then
  command -v gmsh >/dev/null || { echo "python_vs_cli: gmsh is needed to make $mesh" >&2; exit 1; }
  mkdir -p bench/data
  echo "making $mesh (a few minutes of gmsh meshing)..."
  gmsh bench/geo/bracket_1m.geo -2 -format msh41 -bin -o "$mesh" >/dev/null
fi
ascii=bench/data/bracket_1m_ascii.msh  # the same mesh as ASCII, for the reader's other speed
if [[ ! -f $ascii ]] && command -v gmsh >/dev/null; then
  gmsh "$mesh" -save -format msh41 -setnumber Mesh.Binary 0 -o "$ascii" >/dev/null
fi
PYTHONPATH="$build/python" /usr/bin/python3 bench/python_vs_cli.py "$mesh" "$build/lancer" $([[ -f $ascii ]] && echo "$ascii")
