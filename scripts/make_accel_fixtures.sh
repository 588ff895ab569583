#!/usr/bin/env bash
# Regenerates the accelerator test meshes tests/data/accel/*.msh from their .geo files with gmsh.
# Run after editing a .geo; the .msh files are committed so the tests do not need gmsh.
set -euo pipefail
dir=$(cd "$(dirname "$0")/../tests/data/accel" && pwd)
for geo in "$dir"/*.geo; do
  msh=${geo%.geo}.msh
  gmsh -2 "$geo" -o "$msh" > /dev/null
  echo "wrote $msh"
done
