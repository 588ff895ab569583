#!/usr/bin/env bash
# Regenerates the .msh fixtures with post-processing fields in tests/data/fields/ from
# tests/data/geo/field_square.geo with the real gmsh: the unit square with a view whose value is
# x + 2 y, saved as $NodeData or $ElementData in MSH 2.2 and 4.1, ASCII and binary; and the mesh of
# examples/field.toml. They live apart
# from tests/data/msh/ because that folder's files must all be in gmsh_reference.tsv.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v gmsh >/dev/null || { echo "make_field_fixtures.sh: gmsh is not installed (apt-get install gmsh)" >&2; exit 1; }

out=$(realpath tests/data/fields)
rm -f "$out"/*.msh
for kind in node element; do
  for format in 2.2 4.1; do
    for binary in 0 1; do
      encoding=ascii
      [[ $binary == 1 ]] && encoding=bin
      file="$out/${kind}_xy_v${format/./}_${encoding}.msh"
      log=$(gmsh tests/data/geo/field_square.geo -0 -setnumber elementData "$([[ $kind == element ]] && echo 1 || echo 0)" \
        -setstring out "$file" -setnumber Mesh.MshFileVersion "$format" -setnumber Mesh.Binary "$binary" 2>&1)
      if grep -q '^Error' <<<"$log" || [[ ! -s $file ]]; then echo "$log" >&2; exit 1; fi
    done
  done
done
# 8-node quads: lancer adds a centre node to each, whose value it must derive like its position.
log=$(gmsh tests/data/geo/field_square.geo -0 -setnumber elementData 0 -setstring out "$out/node_quad8_v41_ascii.msh" \
  -setnumber Mesh.MshFileVersion 4.1 -setnumber Mesh.Binary 0 -setnumber Mesh.RecombineAll 1 \
  -setnumber Mesh.ElementOrder 2 -setnumber Mesh.SecondOrderIncomplete 1 2>&1)
if grep -q '^Error' <<<"$log" || [[ ! -s $out/node_quad8_v41_ascii.msh ]]; then echo "$log" >&2; exit 1; fi

# A vector field: colours show its magnitude.
log=$(gmsh tests/data/geo/field_square.geo -0 -setnumber vector 1 -setstring out "$out/node_vector_v41_bin.msh" \
  -setnumber Mesh.MshFileVersion 4.1 -setnumber Mesh.Binary 1 2>&1)
if grep -q '^Error' <<<"$log" || [[ ! -s $out/node_vector_v41_bin.msh ]]; then echo "$log" >&2; exit 1; fi

# A volume-only tet10 cube with $ElementData: the faces lancer renders are split second-order skin
# faces of the tetrahedra, each must carry its tetrahedron's value.
log=$(gmsh tests/data/geo/field_square.geo -0 -setnumber elementData 1 -setnumber volume 1 \
  -setstring out "$out/element_tet10_v41_bin.msh" -setnumber Mesh.MshFileVersion 4.1 -setnumber Mesh.Binary 1 2>&1)
if grep -q '^Error' <<<"$log" || [[ ! -s $out/element_tet10_v41_bin.msh ]]; then echo "$log" >&2; exit 1; fi
rm -f tests/data/geo/field_square.geo_unrolled

# Element data of 3 components: arrows stand at the elements' centroids (the square's triangles,
# and the split second-order skin faces of the tet10 cube, one arrow per drawn element face).
log=$(gmsh tests/data/geo/field_square.geo -0 -setnumber vector 1 -setnumber elementData 1 \
  -setstring out "$out/element_vector_v41_bin.msh" -setnumber Mesh.MshFileVersion 4.1 -setnumber Mesh.Binary 1 2>&1)
if grep -q '^Error' <<<"$log" || [[ ! -s $out/element_vector_v41_bin.msh ]]; then echo "$log" >&2; exit 1; fi
log=$(gmsh tests/data/geo/field_square.geo -0 -setnumber vector 1 -setnumber elementData 1 -setnumber volume 1 \
  -setstring out "$out/element_vector_tet10_v41_bin.msh" -setnumber Mesh.MshFileVersion 4.1 -setnumber Mesh.Binary 1 2>&1)
if grep -q '^Error' <<<"$log" || [[ ! -s $out/element_vector_tet10_v41_bin.msh ]]; then echo "$log" >&2; exit 1; fi
rm -f tests/data/geo/field_square.geo_unrolled

# Element data of 3 x + y sampled at the centroids of a regular grid of quads (gmsh's Python API):
# the closed form that isolines of element data are checked against.
/usr/bin/python3 tests/data/geo/element_centroid_grid.py "$out/element_centroids_grid_v41_ascii.msh"

# The example of examples/field.toml (the .geo names its output, beside it).
log=$(cd examples/meshes && gmsh field_sphere.geo -0 2>&1)
if grep -q '^Error' <<<"$log" || [[ ! -s examples/meshes/field_sphere.msh ]]; then echo "$log" >&2; exit 1; fi
rm -f examples/meshes/field_sphere.geo_unrolled
echo "field fixtures: $(ls "$out"/*.msh | wc -l) files, $(du -sh "$out" | cut -f1)"
