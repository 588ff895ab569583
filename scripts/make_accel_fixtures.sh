#!/usr/bin/env bash
# Regenerates the accelerator test meshes tests/data/accel/*.msh with gmsh: each .geo there, and a
# gmsh tutorial model as its authors wrote it (t5: a cube with spherical holes, curved faces meeting
# at many angles; from the gmsh-doc package, apt-get install gmsh-doc). Run after editing a .geo; the .msh files are committed
# so the tests do not need gmsh.
set -euo pipefail
dir=$(cd "$(dirname "$0")/../tests/data/accel" && pwd)
for geo in "$dir"/*.geo; do
  msh=${geo%.geo}.msh
  gmsh -2 "$geo" -o "$msh" > /dev/null
  echo "wrote $msh"
done
tutorial=/usr/share/doc/gmsh-doc/doc/gmsh/tutorial/t5.geo.gz
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
zcat "$tutorial" > "$work/t5.geo"
# -save_all: t5 puts only its volume in a physical group, so the surfaces would not be saved.
gmsh -2 -save_all "$work/t5.geo" -o "$dir/gmsh_tutorial_t5.msh" > /dev/null
echo "wrote $dir/gmsh_tutorial_t5.msh"
