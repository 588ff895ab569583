#!/usr/bin/env bash
# Regenerates tests/data/volume/, the volumes with fields inside them that slices, isosurfaces,
# field lines and probes are tested on, from the .geo and .pro files of scripts/volume_fixtures/:
#   capacitor.msh  a parallel-plate capacitor in a grounded air box (capacitor.geo), solved by the
#                  real GetDP (Debian's getdp 3.2) with its template Lib_Electrostatics_v.pro
#                  (capacitor.pro). `getdp -v2` prints the potential v and the field e = -grad v as
#                  MSH 2.2 files with $ElementNodeData, each with its own copy of the air's mesh; their
#                  data sections are appended verbatim to gmsh's mesh (MSH 2.2, the tetrahedra of the
#                  air and the triangles of the plates and the box, with physical groups), whose
#                  element numbers GetDP keeps. (Merging the .pos files in gmsh would load that mesh a
#                  second time.)
#   mixed.msh      a unit box of hexahedra, tetrahedra, pyramids and prisms (mixed.geo) with node fields
#                  f = x + 2 y + 3 z and r = distance to (0.5, 0.5, 0.5), written by gmsh's API.
#   cube_hex.msh   6 x 6 x 6 hexahedra (cube_hex.geo): f (nodes), g = f at centroids (elements), and the
#                  vectors u = (1, 2, 3) and dipole (a point dipole below the cube) at nodes.
#   moving.msh     the same hexahedra with three steps (times 0, 1, 2) of a scalar s = x - t / 4 and a
#                  vector w turning about z: isosurfaces and field lines over time steps.
# Deterministic: one thread, fixed sizes and seed. Runs from any folder.
set -euo pipefail
cd "$(dirname "$0")/.."
for tool in gmsh getdp; do
  command -v "$tool" >/dev/null ||
    { echo "make_volume_fixtures.sh: $tool is not installed (apt-get install $tool)" >&2; exit 1; }
done
/usr/bin/python3 -c 'import gmsh' 2>/dev/null || {
  echo "make_volume_fixtures.sh: /usr/bin/python3 lacks the gmsh module (apt-get install python3-gmsh)" >&2; exit 1; }

sources=$(realpath scripts/volume_fixtures)
mkdir -p tests/data/volume
out=$(realpath tests/data/volume)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# gmsh prints its errors but may still exit 0: fail on any line starting with "Error".
run_logged() {
  local log
  if ! log=$("$@" 2>&1) || grep -q '^Error' <<<"$log"; then echo "$log" >&2; exit 1; fi
}

# capacitor.msh: mesh with gmsh, solve and print with GetDP, then put GetDP's data behind the mesh.
template=/usr/share/doc/getdp/examples/templates/Lib_Electrostatics_v.pro
[[ -f $template ]] ||
  { echo "make_volume_fixtures.sh: GetDP's template $template is missing (apt-get install getdp)" >&2; exit 1; }
cp "$sources/capacitor.geo" "$sources/capacitor.pro" "$template" "$work/"
(
  cd "$work"
  run_logged gmsh capacitor.geo -3 -format msh22 -o capacitor.msh
  run_logged getdp capacitor.pro -msh capacitor.msh -solve Electrostatics_v -pos Electrostatics_v -v2
  for field in v e; do
    [[ -s res/$field.pos ]] || { echo "make_volume_fixtures.sh: getdp wrote no res/$field.pos" >&2; exit 1; }
    sed -n '/^\$ElementNodeData$/,/^\$EndElementNodeData$/p' "res/$field.pos" >>capacitor.msh
  done
)
cp "$work/capacitor.msh" "$out/capacitor.msh"

/usr/bin/python3 "$sources/volume_fields.py" mixed "$sources/mixed.geo" "$out/mixed.msh"
/usr/bin/python3 "$sources/volume_fields.py" cube_hex "$sources/cube_hex.geo" "$out/cube_hex.msh"
/usr/bin/python3 "$sources/volume_fields.py" moving "$sources/cube_hex.geo" "$out/moving.msh"

# What gmsh reads back: element counts and fields, each on the file's own elements and nodes.
/usr/bin/python3 "$sources/volume_fields.py" check "$out/capacitor.msh" v e
/usr/bin/python3 "$sources/volume_fields.py" check "$out/mixed.msh" f r
/usr/bin/python3 "$sources/volume_fields.py" check "$out/cube_hex.msh" f g u dipole
/usr/bin/python3 "$sources/volume_fields.py" check "$out/moving.msh" s w
echo "volume fixtures: $(ls "$out"/*.msh | wc -l) files, $(du -sh "$out" | cut -f1)"
