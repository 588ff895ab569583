#!/usr/bin/env bash
# Regenerates the .msh test fixtures in tests/data/msh/ from the .geo files in tests/data/geo/ with
# the real gmsh, then derives the variants gmsh cannot write directly (CRLF line endings, extra
# sections) and the corpus of broken files in tests/data/msh/broken/ by editing gmsh's output.
# Run it after changing a .geo file or the corpus, and commit the results with the reason.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v gmsh >/dev/null || { echo "make_fixtures.sh: gmsh is not installed (apt-get install gmsh)" >&2; exit 1; }

geo=tests/data/geo
out=tests/data/msh
mkdir -p "$out" "$out/broken"
rm -f "$out"/*.msh "$out"/broken/*.msh

# quiet: runs gmsh, showing its output only when it fails or reports an error.
source scripts/gmsh_quiet.sh

# mesh NAME GEO DIM FORMAT(msh22|msh40|msh41) ENCODING(ascii|bin) [gmsh options...]
mesh() {
  local name=$1 file=$2 dim=$3 format=$4 encoding=$5
  shift 5
  local binary=0
  [[ $encoding == bin ]] && binary=1
  quiet gmsh "$geo/$file.geo" "-$dim" -format "$format" -setnumber Mesh.Binary "$binary" "$@" \
    -o "$out/${name}_${format/msh/v}_${encoding}.msh"
}

recombine=(-setnumber Mesh.RecombineAll 1)
incomplete=(-setnumber Mesh.SecondOrderIncomplete 1)

# The unit square as every surface element type, in every format and encoding gmsh writes.
for format in msh22 msh40 msh41; do
  for encoding in ascii bin; do
    [[ $format == msh40 && $encoding == bin ]] && continue  # gmsh 4.8 writes MSH 4.0 in ASCII only
    mesh square_tri3 square 2 $format $encoding
    mesh square_quad4 square 2 $format $encoding "${recombine[@]}"
    mesh square_tri6 square 2 $format $encoding -order 2
    mesh square_quad9 square 2 $format $encoding "${recombine[@]}" -order 2
    mesh square_quad8 square 2 $format $encoding "${recombine[@]}" -order 2 "${incomplete[@]}"
    mesh square_tri10 square 2 $format $encoding -order 3
  done
done

# Volume-only files: lancer renders the skin.
for format in msh22 msh41; do
  for encoding in ascii bin; do
    mesh cube_tet4 cube_tet 3 $format $encoding
    mesh cube_tet10 cube_tet 3 $format $encoding -order 2
  done
done
mesh cube_tet4_saveall cube_tet 3 msh41 ascii -save_all
mesh cube_tet10_saveall cube_tet 3 msh41 bin -save_all -order 2
for spec in "msh41 ascii" "msh22 bin"; do
  mesh cube_hex8 cube_hex 3 $spec
  mesh cube_hex27 cube_hex 3 $spec -order 2
  mesh cube_hex20 cube_hex 3 $spec -order 2 "${incomplete[@]}"
done
mesh prism6 prism 3 msh41 ascii
mesh prism6 prism 3 msh41 bin
mesh prism18 prism 3 msh41 bin -order 2
mesh prism15 prism 3 msh22 ascii -order 2 "${incomplete[@]}"

# A closed sphere, whole and in two partitions.
for spec in "msh41 ascii" "msh41 bin" "msh22 ascii"; do mesh sphere sphere 2 $spec; done
for spec in "msh41 ascii" "msh41 bin" "msh22 ascii" "msh22 bin"; do mesh sphere_part2 sphere 2 $spec -part 2; done

# Far from the origin, and with sparse node tags (no renumbering after saving one of two surfaces).
mesh far_square far_square 2 msh41 bin
mesh far_square far_square 2 msh22 ascii
for spec in "msh41 ascii" "msh41 bin" "msh22 ascii" "msh22 bin"; do
  mesh sparse_tags two_plates 2 $spec -setnumber Mesh.Renumber 0
done

# Post-processing data ($InterpolationScheme, $NodeData or $ElementData) after the mesh, as gmsh's
# Save View writes it.
for spec in "nodedata NodeData 4.1 1 v41_bin" "nodedata NodeData 2.2 0 v22_ascii" \
            "elementdata ElementData 4.1 0 v41_ascii" "elementdata ElementData 2.2 1 v22_bin"; do
  read -r name type version binary suffix <<<"$spec"
  cat >"$out/nodedata.geo" <<GEO
Include "../geo/square.geo";
Mesh 2;
Plugin(NewView).NumComp = 1;
Plugin(NewView).Type = "$type";
Plugin(NewView).Run;
PostProcessing.SaveMesh = 1;
Mesh.MshFileVersion = $version;
Mesh.Binary = $binary;
Save View[0] "${name}_$suffix.msh";
GEO
  (cd "$out" && quiet gmsh nodedata.geo -0 -o nodedata.geo_unrolled)
  rm -f "$out/nodedata.geo" "$out/nodedata.geo_unrolled"
done

python3 - "$out" <<'PY'
import pathlib, random, struct, sys

out = pathlib.Path(sys.argv[1])
broken = out / "broken"

def read(name):
    return (out / name).read_bytes()

def write(name, data):
    (broken / name).write_bytes(data)

def replace_once(data, old, new):
    assert old in data, (old, data[:200])
    return data.replace(old, new, 1)

# Derived valid variants: Windows line endings, comments and an unknown section.
tri3 = read("square_tri3_v41_ascii.msh")
(out / "square_tri3_v41_ascii_crlf.msh").write_bytes(tri3.replace(b"\n", b"\r\n"))
(out / "square_tri3_v22_ascii_crlf.msh").write_bytes(read("square_tri3_v22_ascii.msh").replace(b"\n", b"\r\n"))
extras = replace_once(tri3, b"$EndMeshFormat\n",
                      b"$EndMeshFormat\n$Comments\nmade by make_fixtures.sh; $Nodes here is not a section\n"
                      b"$EndComments\n$LancerUnknownSection\n1 2 3\n$EndLancerUnknownSection\n")
(out / "square_tri3_v41_ascii_extras.msh").write_bytes(extras)

# Broken files: each is a small edit of a gmsh-written fixture (tests assert the messages).
b41 = read("square_tri3_v41_bin.msh")
b22 = read("square_tri3_v22_bin.msh")
a22 = read("square_tri3_v22_ascii.msh")
a40 = read("square_tri3_v40_ascii.msh")
write("empty.msh", b"")
rng = random.Random(2)
write("random_bytes.msh", bytes(rng.randrange(256) for _ in range(4096)))
write("msh1.msh", b"$NOD\n1\n1 0 0 0\n$ENDNOD\n$ELM\n0\n$ENDELM\n")
write("version_4_2.msh", replace_once(tri3, b"4.1 0 8", b"4.2 0 8"))
write("version_5.msh", replace_once(tri3, b"4.1 0 8", b"5.0 0 8"))
write("file_type_7.msh", replace_once(tri3, b"4.1 0 8", b"4.1 7 8"))
write("data_size_4.msh", replace_once(b41, b"4.1 1 8", b"4.1 1 4"))
head = b41.index(b"4.1 1 8\n") + len(b"4.1 1 8\n")
write("byte_swapped.msh", b41[:head] + struct.pack(">i", 1) + b41[head + 4:])
write("bad_check_word.msh", b41[:head] + struct.pack("<i", 7) + b41[head + 4:])
write("only_mesh_format.msh", tri3[:tri3.index(b"$PhysicalNames")])
write("no_end_mesh_format.msh", replace_once(tri3, b"$EndMeshFormat", b"$EndMeshFormt"))
write("truncated_nodes_ascii.msh", tri3[:tri3.index(b"$EndNodes") - 40])
write("truncated_elements_ascii.msh", tri3[:tri3.index(b"$EndElements") - 25])
write("truncated_nodes_bin.msh", b41[:b41.index(b"$Nodes") + 200])
write("truncated_elements_bin.msh", b41[:b41.index(b"$Elements") + 300])
write("truncated_nodes_v22_bin.msh", b22[:b22.index(b"$Nodes") + 100])
write("missing_end_elements.msh", tri3[:tri3.index(b"$EndElements")])
# 4.1 ASCII: the first triangle names a node that does not exist.
nodes_end = tri3.index(b"$EndNodes")
lines = tri3.split(b"\n")
tri_block = next(i for i, l in enumerate(lines) if l.startswith(b"2 1 2 "))
fields = lines[tri_block + 1].split(b" ")
fields[1] = b"9001"
lines[tri_block + 1] = b" ".join(fields)
write("missing_node_v41.msh", b"\n".join(lines))
lines22 = a22.split(b"\n")
first22 = lines22.index(b"$Elements") + 2
tri22 = next(i for i in range(first22, len(lines22)) if lines22[i].split()[1] == b"2")
fields = lines22[tri22].split(b" ")
fields[-1] = b"777"
lines22[tri22] = b" ".join(fields)
write("missing_node_v22.msh", b"\n".join(lines22))
write("nan_coordinate.msh", replace_once(a22, b"\n2 1 0 0\n", b"\n2 nan 0 0\n"))
write("inf_coordinate.msh", replace_once(tri3, b"\n1 0 0\n", b"\n1 inf 0\n"))
coords = b41.index(b"$Nodes") + len(b"$Nodes\n") + 32 + 20 + 8  # header, first block header, its tag
write("nan_coordinate_bin.msh", b41[:coords] + struct.pack("<d", float("nan")) + b41[coords + 8:])
write("huge_node_count.msh", replace_once(tri3, b"$Nodes\n9 25 1 25", b"$Nodes\n9 999999999999 1 25"))
nodes_header = b41.index(b"$Nodes\n") + len(b"$Nodes\n")
write("huge_node_count_bin.msh", b41[:nodes_header + 8] + struct.pack("<Q", 2**62) + b41[nodes_header + 16:])
write("huge_element_count_v22.msh", replace_once(a22, b"$Elements\n", b"$Elements\n123456789012") )
write("node_count_mismatch.msh", replace_once(tri3, b"$Nodes\n9 25 1 25", b"$Nodes\n9 24 1 25"))
write("negative_count.msh", replace_once(a22, b"$Nodes\n25", b"$Nodes\n-25"))
write("bad_number.msh", replace_once(a22, b"\n2 1 0 0\n", b"\n2 1.0abc 0 0\n"))
write("unknown_element_type.msh", replace_once(tri3, b"\n2 1 2 ", b"\n2 1 999 "))
write("polygon_element_type.msh", replace_once(a22, b" 2 2 1 1 ", b" 34 2 1 1 "))
write("elements_before_nodes.msh",
      tri3[:tri3.index(b"$Nodes")] + tri3[tri3.index(b"$Elements"):] )
dup = replace_once(a22, b"\n2 1 0 0\n", b"\n1 1 0 0\n")
write("duplicate_node_tag.msh", dup)
write("unterminated_name.msh", replace_once(tri3, b'"plate"', b'"plate'))
write("unclosed_section.msh", replace_once(tri3, b"$EndPeriodic", b"$EndPeriodik"))
write("stray_end.msh", replace_once(tri3, b"$PhysicalNames", b"$EndNodes\n$PhysicalNames"))
write("garbage_between_sections.msh", replace_once(tri3, b"$Entities", b"hello\n$Entities"))
write("binary_v40.msh", replace_once(a40, b"4 0 8\n", b"4 1 8\n\x01\x00\x00\x00\n"))
PY
echo "fixtures: $(ls "$out"/*.msh | wc -l) files, broken corpus: $(ls "$out"/broken/*.msh | wc -l) files, $(du -sh "$out" | cut -f1)"
scripts/gmsh_reference.sh  # what gmsh itself reports for each fixture, the oracle of msh_gmsh_reference_test
scripts/make_reader_fixtures.sh  # tests/data/reader: groups, order 3+, nothing to draw, appended views, non-mesh files
scripts/make_surface_fixtures.sh  # tests/data/surface: STL by gmsh, OBJ and PLY by meshio
