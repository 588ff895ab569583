#!/usr/bin/env bash
# Asks gmsh itself what each .msh fixture in tests/data/msh/ holds, and writes its answers to
# tests/data/msh/gmsh_reference.tsv, the oracle of tests/mesh/msh_gmsh_reference_test.cpp:
#   - node and element counts: gmsh's read-only options Mesh.NbNodes, Mesh.NbTriangles, ...
#     after merging the file (gmsh counts elements of every order: a 6-node triangle is a triangle);
#   - bounding box: Min/Max of the views that Plugin(MathEval) makes with "x", "y" and "z" on the
#     mesh (the nodes of its elements, not unused nodes as General.MinX would include);
#   - area: Plugin(Integrate) of the constant 1 over the 2D elements, or, for a volume-only file,
#     over the boundary Plugin(Skin) extracts (gmsh integrates second-order elements exactly).
# Run by scripts/make_fixtures.sh after it regenerates the fixtures; needs only gmsh.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v gmsh >/dev/null || { echo "gmsh_reference.sh: gmsh is not installed (apt-get install gmsh)" >&2; exit 1; }

out=tests/data/msh
table=$out/gmsh_reference.tsv
probe=$(mktemp --suffix=.geo)
trap 'rm -f "$probe" "${probe}_unrolled"' EXIT

{
  echo "# Written by scripts/gmsh_reference.sh with $(gmsh --version 2>&1): what gmsh reports for each fixture."
  printf "#file\tnodes\ttriangles\tquadrangles\ttetrahedra\thexahedra\tprisms\tpyramids"
  printf "\txmin\tymin\tzmin\txmax\tymax\tzmax\tarea\n"
  for path in "$out"/*.msh; do
    file=$(basename "$path")
    cat >"$probe" <<GEO
Merge "$(realpath "$path")";
v = PostProcessing.NbViews;  // views the file itself holds (its NodeData) come first
Printf("REF counts %g %g %g %g %g %g %g", Mesh.NbNodes, Mesh.NbTriangles, Mesh.NbQuadrangles,
       Mesh.NbTetrahedra, Mesh.NbHexahedra, Mesh.NbPrisms, Mesh.NbPyramids);
Plugin(NewView).NumComp = 1;
Plugin(NewView).Run;  // View[v]: the mesh with zero node values
Plugin(MathEval).View = v;
Plugin(MathEval).Expression0 = "x";
Plugin(MathEval).Run;
Plugin(MathEval).Expression0 = "y";
Plugin(MathEval).Run;
Plugin(MathEval).Expression0 = "z";
Plugin(MathEval).Run;
Printf("REF bbox %.17g %.17g %.17g %.17g %.17g %.17g", View[v + 1].Min, View[v + 2].Min,
       View[v + 3].Min, View[v + 1].Max, View[v + 2].Max, View[v + 3].Max);
Plugin(MathEval).Expression0 = "1";
Plugin(MathEval).Run;
If (Mesh.NbTriangles + Mesh.NbQuadrangles == 0)
  Plugin(Skin).View = v + 4;
  Plugin(Skin).Run;
EndIf
Plugin(Integrate).View = PostProcessing.NbViews - 1;
Plugin(Integrate).Dimension = 2;
Plugin(Integrate).Run;
Printf("REF area %.17g", View[PostProcessing.NbViews - 1].Max);
GEO
    # The exit status is not checked: gmsh fails to unroll partitioned files into .geo after
    # answering; a missing answer below is the failure that matters.
    log=$(gmsh "$probe" -0 2>&1) || true
    counts=$(sed -n 's/^REF counts //p' <<<"$log")
    bbox=$(sed -n 's/^REF bbox //p' <<<"$log")
    area=$(sed -n 's/^REF area //p' <<<"$log")
    [[ -n $counts && -n $bbox && -n $area ]] || { echo "gmsh_reference.sh: no answer for $file:" >&2; echo "$log" >&2; exit 1; }
    printf "%s\t%s\t%s\t%s\n" "$file" "${counts// /$'\t'}" "${bbox// /$'\t'}" "$area"
  done
} >"$table.tmp"
mv "$table.tmp" "$table"
echo "gmsh_reference.sh: $(grep -vc '^#' "$table") fixtures in $table"
