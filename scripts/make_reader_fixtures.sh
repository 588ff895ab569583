#!/usr/bin/env bash
# Regenerates, with the real gmsh, the fixtures in tests/data/reader/: files as gmsh writes them that
# test how lancer reads models (entities in several physical groups, reversed groups, elements of
# order 3 and up, files with nothing to draw, views appended to a mesh, values for unsaved nodes) and
# the non-mesh files people give it (STL, STEP, BREP, VTK, .pos), from the .geo and .py files there
# and in tests/data/geo/. The derived variants gmsh does not write (a misspelt end marker as in
# gmsh's own tutorial view5.msh, an unreadable field section) are edits of gmsh output. Called by
# make_fixtures.sh; runs alone too. Needs gmsh and python3-gmsh (/usr/bin/python3).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v gmsh >/dev/null || { echo "make_reader_fixtures.sh: gmsh is not installed" >&2; exit 1; }

geo=tests/data/geo
out=tests/data/reader
rm -f "$out"/*.msh "$out"/*.stl "$out"/*.step "$out"/*.brep "$out"/*.vtk "$out"/*.pos

# quiet: runs gmsh, showing its output only when it fails or reports an error.
source scripts/gmsh_quiet.sh

# Physical groups: an entity in two groups, a group taking a surface reversed (tag -3 in MSH 4.1).
for spec in "msh41 0 v41_ascii" "msh41 1 v41_bin" "msh22 0 v22_ascii" "msh22 1 v22_bin"; do
  read -r format binary suffix <<<"$spec"
  quiet gmsh "$out/two_plates_groups.geo" -2 -format "$format" -setnumber Mesh.Binary "$binary" \
    -o "$out/two_plates_groups_$suffix.msh"
done

# Nothing to draw: only lines (-1), Physical Volumes meshed in 2D, no elements at all (-0).
for format in msh41 msh22; do
  quiet gmsh "$out/outline_only.geo" -1 -format $format -o "$out/outline_only_${format/msh/v}_ascii.msh"
  quiet gmsh "$out/box_volume_group.geo" -2 -format $format -o "$out/box_volume_group_2d_${format/msh/v}_ascii.msh"
  quiet gmsh "$geo/square.geo" -0 -format $format -o "$out/square_unmeshed_${format/msh/v}_ascii.msh"
done

# Order 3 and 4: surfaces split through their nodes, volumes' skin through their corners.
quiet gmsh "$geo/square.geo" -2 -order 3 -setnumber Mesh.RecombineAll 1 -format msh41 -o "$out/square_quad16_v41_ascii.msh"
quiet gmsh "$geo/square.geo" -2 -order 4 -format msh22 -setnumber Mesh.Binary 1 -o "$out/square_tri15_v22_bin.msh"
quiet gmsh "$geo/cube_tet.geo" -3 -order 3 -format msh41 -setnumber Mesh.Binary 1 -o "$out/cube_tet20_v41_bin.msh"
quiet gmsh "$geo/cube_tet.geo" -3 -order 3 -format msh22 -o "$out/cube_tet20_v22_ascii.msh"
quiet gmsh "$geo/cube_hex.geo" -3 -order 3 -format msh41 -o "$out/cube_hex64_v41_ascii.msh"

# Views appended to a mesh file (the mesh repeated), and values for nodes the file does not save.
for spec in "4.1 0 0 appended_view_v41_ascii" "4.1 1 0 appended_view_v41_bin" "2.2 0 0 appended_view_v22_ascii" \
            "4.1 0 1 partial_view_v41_ascii" "2.2 1 1 partial_view_v22_bin"; do
  read -r version binary partial name <<<"$spec"
  /usr/bin/python3 "$out/appended_view.py" "$out/$name.msh" "$version" "$binary" "$partial"
done

# Files that are not meshes: STL (ASCII and binary), STEP, BREP and VTK made by gmsh from the
# tests' geometry; and a .pos view, which lancer reads (not taken for a foreign file).
quiet gmsh "$geo/sphere.geo" -2 -format stl -o "$out/sphere.stl"
quiet gmsh "$geo/sphere.geo" -2 -format stl -setnumber Mesh.Binary 1 -o "$out/sphere_binary.stl"
quiet gmsh "$geo/cube_tet.geo" -0 -o "$out/box.step"
quiet gmsh "$geo/cube_tet.geo" -0 -o "$out/box.brep"
quiet gmsh "$geo/sphere.geo" -2 -format vtk -o "$out/sphere.vtk"
quiet gmsh "$geo/field_square.geo" -0 -setstring out "$(realpath "$out")/temperature.pos"
rm -f "$geo"/*.geo_unrolled "$out"/*.geo_unrolled

python3 - "$out" <<'PY'
import pathlib, sys

out = pathlib.Path(sys.argv[1])
fields = out.parent / "fields"

def derive(source, name, old, new):
    data = source.read_bytes()
    assert old in data, (source, old)
    (out / name).write_bytes(data.replace(old, new, 1))

# gmsh's own tutorial file view5.msh ends a section with $EndElememtData, and gmsh reads it.
derive(fields / "element_xy_v22_ascii.msh", "misspelt_end_v22_ascii.msh", b"$EndElementData", b"$EndElememtData")
# A $NodeData whose header says 0 components: lancer skips the section with a warning.
derive(fields / "node_xy_v41_ascii.msh", "unreadable_nodedata_v41_ascii.msh",
       b'"temperature"\n1\n-1\n3\n0\n1\n25\n', b'"temperature"\n1\n-1\n3\n0\n0\n25\n')
# A view appended after a mesh that is not the same: a node moved in the repeated $Nodes.
data = (out / "appended_view_v41_ascii.msh").read_bytes()
second = data.index(b"$Nodes", data.index(b"$Nodes") + 1)
(out / "appended_view_changed_v41_ascii.msh").write_bytes(
    data[:second] + data[second:].replace(b"\n0 0 0\n", b"\n0 0 0.5\n", 1))
PY
echo "reader fixtures: $(ls "$out" | grep -vc -e '\.geo$' -e '\.py$') files, $(du -sh "$out" | cut -f1)"
