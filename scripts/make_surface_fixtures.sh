#!/usr/bin/env bash
# Regenerates the fixtures in tests/data/surface/ with real writers: STL (ASCII, one solid per
# physical surface, and binary) by gmsh from box.geo, OBJ and PLY (ASCII, binary little- and
# big-endian) by meshio (Debian's python3-meshio) from gmsh's output, the PLY files carrying a
# node field as a vertex property. The hand-written files there (groups.obj, polygons.ply, ...) are
# not touched. Called by make_fixtures.sh; runs alone too. Needs gmsh and python3-meshio.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v gmsh >/dev/null || { echo "make_surface_fixtures.sh: gmsh is not installed" >&2; exit 1; }
/usr/bin/python3 -c "import meshio" 2>/dev/null ||
  { echo "make_surface_fixtures.sh: meshio is not installed (apt install python3-meshio)" >&2; exit 1; }

out=tests/data/surface
source scripts/gmsh_quiet.sh

quiet gmsh "$out/box.geo" -2 -format stl -o "$out/box_groups.stl"
quiet gmsh "$out/box.geo" -2 -format stl -setnumber Mesh.Binary 1 -o "$out/box_binary.stl"

# meshio's own writers; the plate's temperature (a $NodeData of gmsh's) becomes a vertex property.
/usr/bin/python3 - "$out" <<'PY'
import sys
import meshio
import numpy

out = sys.argv[1]
box = meshio.read(f"{out}/box_groups.stl")
meshio.write(f"{out}/box.obj", meshio.Mesh(box.points, box.cells))
plate = meshio.read("tests/data/fields/node_xy_v22_ascii.msh")
# MSH 2.2 repeats an element once per physical group; meshio keeps the copies, the PLY wants one.
triangles = numpy.concatenate([cells.data for cells in plate.cells if cells.type == "triangle"])
_, first = numpy.unique(numpy.sort(triangles, axis=1), axis=0, return_index=True)
triangles = triangles[numpy.sort(first)]
plate = meshio.Mesh(plate.points, [("triangle", triangles)],
                    point_data={"temperature": plate.point_data["temperature"]})
meshio.write(f"{out}/plate_temperature.ply", plate, binary=False)
meshio.write(f"{out}/plate_temperature_bin.ply", plate, binary=True)
PY
