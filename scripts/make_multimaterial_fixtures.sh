#!/usr/bin/env bash
# Regenerates, with the real gmsh, the multi-material meshes of the interface tests
# (tests/data/multimaterial) from their committed .geo files: several physical volumes meshed
# together, in MSH 4.1 and 2.2, first and second order, tetrahedra and hexahedra, and with
# -save_all (every surface element written too). Needs gmsh (apt-get install gmsh).
set -euo pipefail
cd "$(dirname "$0")/../tests/data/multimaterial"
command -v gmsh >/dev/null || { echo "make_multimaterial_fixtures: gmsh is not installed" >&2; exit 1; }
# mesh GEO OUT FORMAT [gmsh options...]
mesh() {
  local geo=$1 out=$2 format=$3
  shift 3
  gmsh "$geo.geo" -3 -format "$format" "$@" -o "$out.msh" >/dev/null
  rm -f "$geo.geo_unrolled"
}
mesh cube_sphere cube_sphere_v41 msh41 -bin
mesh cube_sphere cube_sphere_v22 msh22
mesh cube_sphere cube_sphere_o2_v41 msh41 -bin -order 2 -clscale 1.5
mesh cube_sphere cube_sphere_saveall_v41 msh41 -bin -save_all
mesh cube_sphere_nogroups cube_sphere_nogroups_v41 msh41 -bin
mesh box_cylinder_hex box_cylinder_hex_v41 msh41 -bin
mesh box_cylinder_hex box_cylinder_hex27_v41 msh41 -bin -order 2 -clscale 1.5
mesh glass_water_slabs glass_water_slabs_v41 msh41 -bin
mesh three_materials three_materials_v41 msh41 -bin
# Surfaces only: the slabs' boundaries, meshed in 2D.
gmsh slabs_surfaces.geo -2 -format msh41 -o slabs_surfaces_v41.msh >/dev/null
