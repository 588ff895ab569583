// The catalogue's cases (bad_input_cases.hpp); the inputs are made in a scratch folder per case.
#include "util/bad_input_cases.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "support/files.hpp"
#include "support/test_images.hpp"

namespace lancer::bad_input {
namespace {

namespace fs = std::filesystem;

using test::dataFile;

// ---- inputs ------------------------------------------------------------------------------------

// A small valid scene around part.msh (a committed gmsh fixture), with `extra` appended and `render`
// lines inside [render] after `size`.
std::string scene(const std::string& render = "", const std::string& extra = "",
                  const std::string& size = "width = 16\nheight = 12\n") {
  return "[render]\n" + size + render +
         "\n[[light]]\nposition = [2, 2, 2]\n\n[[mesh]]\nfile = \"part.msh\"\n" + extra;
}

std::function<void(const Scratch&)> withScene(const std::string& text) {
  return [text](const Scratch& s) {
    s.copy(dataFile("msh/square_tri3_v41_ascii.msh"), "part.msh");
    s.write("scene.toml", text);
  };
}

// withScene, and a flat 8x4 Radiance map sky.hdr of grey pixels.
std::function<void(const Scratch&)> withMap(const std::string& text) {
  return [text](const Scratch& s) {
    withScene(text)(s);
    std::string map = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n";
    for (int i = 0; i < 32; ++i) map += "\x80\x80\x80\x81";
    s.write("sky.hdr", map);
  };
}

// A scene whose mesh is coloured by a field (for --legend), and an existing out.png.
std::function<void(const Scratch&)> withFieldScene() {
  return [](const Scratch& s) {
    s.copy(dataFile("fields/node_xy_v22_ascii.msh"), "field.msh");
    s.write("scene.toml",
            "[render]\nwidth = 16\nheight = 12\n[[mesh]]\nfile = \"field.msh\"\n"
            "color_by = { field = \"temperature\" }\n");
    s.write("out.png", "old image");
  };
}

Case sceneCase(std::string id, std::string what, std::string input, const std::string& text) {
  return {std::move(id),
          std::move(what),
          std::move(input),
          withScene(text),
          "$LANCER render -q scene.toml -o out.png",
          nullptr};
}

Case mshCase(const std::string& file, std::string what) {
  const std::string id = "msh_" + file.substr(0, file.size() - 4);
  return {id,
          std::move(what),
          "`tests/data/msh/broken/" + file + "`",
          [file](const Scratch& s) { s.copy(dataFile("msh/broken/" + file), file); },
          "$LANCER info " + file,
          nullptr};
}

// `lancer render` of a gmsh-made file in tests/data/reader/ (scripts/make_reader_fixtures.sh).
Case readerCase(std::string id, std::string what, const std::string& file, const std::string& as = "") {
  const std::string name = as.empty() ? file : as;
  return {std::move(id),
          std::move(what),
          "`tests/data/reader/" + file + "`" + (as.empty() ? "" : " as `" + as + "`"),
          [file, name](const Scratch& s) { s.copy(dataFile("reader/" + file), name); },
          "$LANCER render -q " + name + " -o out.png",
          nullptr};
}

// `lancer render` of a file `name` holding `text`.
Case surfaceCase(std::string id, std::string what, std::string input, const std::string& name,
                 std::string text) {
  Case c{
      std::move(id), std::move(what), std::move(input), nullptr, "$LANCER render -q " + name + " -o out.png",
      nullptr};
  c.setUp = [name, text = std::move(text)](const Scratch& s) { s.write(name, text); };
  return c;
}

// After a failed write: the old out.png is intact and nothing else is in the folder `folder`.
std::function<void(const Scratch&)> oldOutputKept(const std::string& file, const std::string& folder = "") {
  return [file, folder](const Scratch& s) {
    EXPECT_EQ(s.read(file), "old image") << "the existing output was changed";
    for (const std::string& name : s.entriesBelow()) {
      const bool inFolder =
          folder.empty() ? name.find('/') == std::string::npos : name.rfind(folder + "/", 0) == 0;
      if (inFolder) {
        EXPECT_EQ(name.find(".tmp-"), std::string::npos) << "temporary file left: " << name;
      }
    }
  };
}

}  // namespace

std::vector<Case> catalogue() {
  std::vector<Case> cases = {
      // --- gmsh .msh files (the committed broken corpus, made by editing gmsh output) ---
      mshCase("empty.msh", "empty file"),
      mshCase("random_bytes.msh", "not a mesh at all"),
      mshCase("msh1.msh", "MSH 1 format"),
      mshCase("version_4_2.msh", "unsupported version 4.2"),
      mshCase("version_5.msh", "unsupported version 5"),
      mshCase("file_type_7.msh", "file type neither ASCII nor binary"),
      mshCase("data_size_4.msh", "4-byte floating point data size"),
      mshCase("binary_v40.msh", "binary MSH 4.0"),
      mshCase("byte_swapped.msh", "byte-swapped (big-endian) binary file"),
      mshCase("bad_check_word.msh", "corrupt endianness check word"),
      mshCase("no_end_mesh_format.msh", "misspelt section end"),
      {"msh_only_mesh_format", "header only, no nodes or elements, rendered",
       "`tests/data/msh/broken/only_mesh_format.msh`",
       [](const Scratch& s) { s.copy(dataFile("msh/broken/only_mesh_format.msh"), "only_mesh_format.msh"); },
       "$LANCER render -q only_mesh_format.msh -o out.png", nullptr},
      mshCase("truncated_nodes_ascii.msh", "truncated inside $Nodes (ASCII)"),
      mshCase("truncated_elements_ascii.msh", "truncated inside $Elements (ASCII)"),
      mshCase("truncated_nodes_bin.msh", "truncated inside $Nodes (binary 4.1)"),
      mshCase("truncated_elements_bin.msh", "truncated inside $Elements (binary 4.1)"),
      mshCase("truncated_nodes_v22_bin.msh", "truncated inside $Nodes (binary 2.2)"),
      mshCase("missing_end_elements.msh", "missing $EndElements"),
      mshCase("missing_node_v41.msh", "element uses an undefined node (4.1)"),
      mshCase("missing_node_v22.msh", "element uses an undefined node (2.2)"),
      mshCase("nan_coordinate.msh", "NaN coordinate (ASCII)"),
      mshCase("inf_coordinate.msh", "infinite coordinate"),
      mshCase("nan_coordinate_bin.msh", "NaN coordinate (binary)"),
      mshCase("huge_node_count.msh", "node count far beyond the file size (ASCII)"),
      mshCase("huge_node_count_bin.msh", "node count far beyond the file size (binary)"),
      mshCase("huge_element_count_v22.msh", "element count far beyond the file size"),
      mshCase("node_count_mismatch.msh", "node blocks disagree with the $Nodes header"),
      mshCase("negative_count.msh", "negative count"),
      mshCase("bad_number.msh", "malformed number"),
      mshCase("unknown_element_type.msh", "unknown element type"),
      mshCase("polygon_element_type.msh", "variable-size element type"),
      mshCase("elements_before_nodes.msh", "sections out of order"),
      mshCase("duplicate_node_tag.msh", "duplicate node tag"),
      mshCase("unterminated_name.msh", "unterminated physical name"),
      mshCase("unclosed_section.msh", "unclosed optional section"),
      mshCase("stray_end.msh", "section end without a start"),
      mshCase("garbage_between_sections.msh", "text between sections"),
      {"msh_missing_file", "mesh file that does not exist", "`lancer info nothing.msh`", nullptr,
       "$LANCER info nothing.msh", nullptr},
      {"msh_directory", "a folder instead of a mesh", "`lancer info folder.msh` (a folder)",
       [](const Scratch& s) { fs::create_directory(s.path() / "folder.msh"); }, "$LANCER info folder.msh",
       nullptr},
      {"msh_device", "a device instead of a mesh", "`lancer info /dev/null`", nullptr,
       "$LANCER info /dev/null", nullptr},
      {"msh_over_memory_budget", "mesh needing more than --max-memory",
       "`--max-memory 1K` and a 25-node mesh",
       [](const Scratch& s) { s.copy(dataFile("msh/square_tri3_v41_ascii.msh"), "part.msh"); },
       "$LANCER info --max-memory 1K part.msh", nullptr},

      // --- scene files ---
      {"scene_missing_file", "scene file that does not exist", "`lancer render nothing.toml`", nullptr,
       "$LANCER render -q nothing.toml -o out.png", nullptr},
      {"scene_directory", "a folder instead of a scene", "`lancer render folder.toml` (a folder)",
       [](const Scratch& s) { fs::create_directory(s.path() / "folder.toml"); },
       "$LANCER render -q folder.toml -o out.png", nullptr},
      sceneCase("scene_toml_syntax", "TOML syntax error", "`width = = 3`", "[render]\nwidth = = 3\n"),
      sceneCase("scene_duplicate_key", "key given twice", "`width = 16` twice",
                "[render]\nwidth = 16\nwidth = 16\n[[mesh]]\nfile = \"part.msh\"\n"),
      sceneCase("scene_binary", "binary garbage instead of TOML", "bytes `ff fe 00 01`",
                std::string("\xff\xfe\x00\x01", 4)),
      sceneCase("scene_wrong_type", "wrong value type", "`width = \"wide\"`",
                "[render]\nwidth = \"wide\"\n[[mesh]]\nfile = \"part.msh\"\n"),
      sceneCase("scene_width_zero", "image width 0", "`width = 0`", scene("", "", "width = 0\n")),
      sceneCase("scene_width_limit", "image wider than the limit", "`width = 40000`",
                "[render]\nwidth = 40000\n[[mesh]]\nfile = \"part.msh\"\n"),
      sceneCase("scene_samples_limit", "samples above the limit", "`samples = 4096`",
                scene("samples = 4096")),
      sceneCase("scene_samples_not_square", "samples not a square for the grid sampler", "`samples = 5`",
                scene("samples = 5")),
      sceneCase("scene_depth_limit", "reflection depth above the limit", "`max_depth = 100`",
                scene("max_depth = 100")),
      sceneCase("scene_frames_limit", "animation frames above the limit", "`[animation] frames = 20000`",
                scene("", "\n[animation]\nframes = 20000\n")),
      sceneCase("scene_unknown_key", "misspelt key", "`widht = 16`",
                "[render]\nwidht = 16\n[[mesh]]\nfile = \"part.msh\"\n"),
      sceneCase("scene_unknown_table", "unknown table", "`[lights]`", scene("", "[lights]\nx = 1\n")),
      sceneCase("scene_nan_colour", "NaN in a colour", "`background = [nan, 0, 0]`",
                scene("background = [nan, 0, 0]")),
      sceneCase("scene_negative_colour", "negative colour component", "`kd = [-1, 0, 0]`",
                scene("", "material = \"m\"\n[material.m]\nkd = [-1, 0, 0]\n")),
      sceneCase("scene_short_vector", "vector with two components", "`position = [1, 2]`",
                "[camera]\nposition = [1, 2]\n[[mesh]]\nfile = \"part.msh\"\n"),
      sceneCase("scene_missing_material", "mesh names an undefined material", "`material = \"gold\"`",
                scene("", "material = \"gold\"\n")),
      sceneCase("scene_unknown_group", "group name the mesh does not have",
                "`groups = { lid = \"default\" }`", scene("", "groups = { lid = \"default\" }\n")),
      sceneCase("scene_missing_mesh", "mesh file that does not exist", "`file = \"gone.msh\"`",
                "[[mesh]]\nfile = \"gone.msh\"\n"),
      sceneCase("scene_mesh_not_msh", "mesh file that is not a mesh", "`file = \"scene.toml\"`",
                "[[mesh]]\nfile = \"scene.toml\"\n"),
      sceneCase("scene_bad_enum", "unknown shading mode", "`shading = \"smooth\"`",
                scene("shading = \"smooth\"")),
      sceneCase("scene_mesh_not_array", "[mesh] instead of [[mesh]]", "`[mesh]`",
                "[mesh]\nfile = \"part.msh\"\n"),
      {"scene_image_over_memory_budget", "image needing more than --max-memory",
       "`--max-memory 1M`, `width = height = 4000`",
       withScene("[render]\nwidth = 4000\nheight = 4000\n[[mesh]]\nfile = \"part.msh\"\n"),
       "$LANCER render -q --max-memory 1M scene.toml -o out.png", nullptr},

      {"scene_non_finite_pixels_whitted", "pixels that come out non-finite, integrator = \"whitted\"",
       "`background = [3e38, 3e38, 3e38]`, `samples = 4` (the sum overflows)",
       withScene(scene("background = [3e38, 3e38, 3e38]\nsamples = 4\nintegrator = \"whitted\"\n")),
       "$LANCER render -q scene.toml -o out.png",
       [](const Scratch& s) { EXPECT_FALSE(fs::exists(s.file("out.png"))); }},
      {"scene_non_finite_pixels_path", "pixels that come out non-finite, integrator = \"path\"",
       "`background = [3e38, 3e38, 3e38]`, `samples = 4` (the sum overflows)",
       withScene(scene("background = [3e38, 3e38, 3e38]\nsamples = 4\nintegrator = \"path\"\n")),
       "$LANCER render -q scene.toml -o out.png",
       [](const Scratch& s) { EXPECT_FALSE(fs::exists(s.file("out.png"))); }},
      {"scene_non_finite_pixels_ao", "pixels that come out non-finite, integrator = \"ao\"",
       "`background = [3e38, 3e38, 3e38]`, `samples = 4` (the sum overflows)",
       withScene(scene("background = [3e38, 3e38, 3e38]\nsamples = 4\nintegrator = \"ao\"\n")),
       "$LANCER render -q scene.toml -o out.png",
       [](const Scratch& s) { EXPECT_FALSE(fs::exists(s.file("out.png"))); }},

      // --- command line ---
      {"cli_no_subcommand", "no subcommand", "`lancer`", nullptr, "$LANCER", nullptr},
      {"cli_unknown_option", "unknown option", "`--widht 3`", withScene(scene()),
       "$LANCER render -q --widht 3 scene.toml -o out.png", nullptr},
      {"cli_width_range", "--width out of range", "`--width 0`", withScene(scene()),
       "$LANCER render -q --width 0 scene.toml -o out.png", nullptr},
      {"cli_samples_not_square", "--samples not a square", "`--samples 3`", withScene(scene()),
       "$LANCER render -q --samples 3 scene.toml -o out.png", nullptr},
      {"cli_bad_max_memory", "--max-memory not a size", "`--max-memory lots`", withScene(scene()),
       "$LANCER render -q --max-memory lots scene.toml -o out.png", nullptr},
      {"cli_bad_pixel", "--pixel outside the image", "`--pixel 99,0`", withScene(scene()),
       "$LANCER render -q --pixel 99,0 scene.toml", nullptr},
      {"cli_elevation_range", "--elevation past the pole", "`--elevation 95`", withScene(scene()),
       "$LANCER render -q --elevation 95 scene.toml -o out.png", nullptr},
      {"cli_bad_background", "--background not a colour", "`--background navyy`", withScene(scene()),
       "$LANCER render -q --background navyy scene.toml -o out.png", nullptr},
      {"cli_transparent_bmp", "--transparent for a format without alpha", "`--transparent -o out.bmp`",
       withScene(scene()), "$LANCER render -q --transparent scene.toml -o out.bmp", nullptr},
      {"cli_animate_stdout", "an animation to stdout", "`animate -o -`", withScene(scene()),
       "$LANCER animate -q scene.toml -o -", nullptr},

      // --- output ---
      {"out_bad_extension", "unknown output extension", "`-o out.tiff`", withScene(scene()),
       "$LANCER render -q scene.toml -o out.tiff", nullptr},
      {"out_missing_folder", "output folder that does not exist", "`-o missing/out.png`", withScene(scene()),
       "$LANCER render -q scene.toml -o missing/out.png", nullptr},
      {"out_is_folder", "output path that is a folder", "`-o taken.png` (a folder)",
       [](const Scratch& s) {
         withScene(scene())(s);
         fs::create_directory(s.path() / "taken.png");
       },
       "$LANCER render -q scene.toml -o taken.png", nullptr},
      {"out_file_size_limit", "disk full / file size limit while writing",
       "`ulimit -f 1` (1 KiB), existing `out.png`",
       [](const Scratch& s) {
         withScene(scene("", "", "width = 256\nheight = 256\n"))(s);
         s.write("out.png", "old image");
       },
       "(ulimit -f 1; exec $LANCER render -q scene.toml -o out.png)", oldOutputKept("out.png")},
      {"out_read_only_folder", "read-only output folder",
       "`-o ro/out.png`, `ro` mode 0555, existing `ro/out.png`",
       [](const Scratch& s) {
         withScene(scene())(s);
         s.write("ro/out.png", "old image");
         ::chmod((s.path() / "ro").c_str(), 0555);
         ::chmod(s.path().c_str(), 0755);
       },
       // Root ignores folder permissions, so as root the command runs as nobody.
       "if [ $(id -u) = 0 ]; then exec setpriv --reuid=65534 --regid=65534 --clear-groups "
       "$LANCER render -q scene.toml -o ro/out.png; else exec $LANCER render -q scene.toml -o ro/out.png; fi",
       oldOutputKept("ro/out.png", "ro")},
      // A still PNG, BMP or PPM is streamed in bands (row 65); a GIF still is held whole.
      {"out_gif_over_memory_budget", "GIF still needing more than --max-memory (held whole for its palette)",
       "`--max-memory 64M`, `width = height = 4000`, `-o out.gif`",
       withScene("[render]\nwidth = 4000\nheight = 4000\n[[mesh]]\nfile = \"part.msh\"\n"),
       "$LANCER render -q --max-memory 64M scene.toml -o out.gif", nullptr},

      // Rows added later go at the end, so that the row numbers cited above the table stay.
      // --- gmsh files with nothing to draw, and files that are not meshes (tests/data/reader) ---
      readerCase("draw_lines_only_v41", "only lines (meshed with -1), MSH 4.1", "outline_only_v41_ascii.msh"),
      readerCase("draw_lines_only_v22", "only lines (meshed with -1), MSH 2.2", "outline_only_v22_ascii.msh"),
      readerCase("draw_no_elements", "model saved unmeshed (-0): no elements",
                 "square_unmeshed_v41_ascii.msh"),
      readerCase("draw_volumes_meshed_2d_v41", "Physical Volumes meshed with -2, MSH 4.1",
                 "box_volume_group_2d_v41_ascii.msh"),
      readerCase("draw_volumes_meshed_2d_v22", "Physical Volumes meshed with -2, MSH 2.2",
                 "box_volume_group_2d_v22_ascii.msh"),
      {"draw_scene_mesh_lines_only", "a scene's mesh has nothing to draw",
       "`file = \"lines.msh\"` (only lines)",
       [](const Scratch& s) {
         s.copy(dataFile("reader/outline_only_v41_ascii.msh"), "lines.msh");
         s.write("scene.toml", "[[mesh]]\nfile = \"lines.msh\"\n");
       },
       "$LANCER render -q scene.toml -o out.png", nullptr},
      readerCase("mesh_changed_before_view", "appended view after a different copy of the mesh",
                 "appended_view_changed_v41_ascii.msh"),
      {"not_mesh_geo", "a .geo script", "`tests/data/geo/cube_tet.geo` as `part.geo`",
       [](const Scratch& s) { s.copy(dataFile("geo/cube_tet.geo"), "part.geo"); },
       "$LANCER render -q part.geo -o out.png", nullptr},
      {"not_mesh_geo_surface", "a .geo script of a surface, to info",
       "`tests/data/geo/square.geo` as `t1.geo`",
       [](const Scratch& s) { s.copy(dataFile("geo/square.geo"), "t1.geo"); }, "$LANCER info t1.geo",
       nullptr},
      readerCase("not_mesh_step", "a STEP model", "box.step", "part.stp"),
      readerCase("not_mesh_brep", "a BREP model", "box.brep", "part.brep"),
      {"pos_binary", "a view in gmsh's older binary format ($PostFormat)",
       "`tests/data/pos/binary_view.pos` as `view.pos`",
       [](const Scratch& s) { s.copy(dataFile("pos/binary_view.pos"), "view.pos"); },
       "$LANCER render -q view.pos -o out.png", nullptr},
      readerCase("not_mesh_vtk", "a VTK file", "sphere.vtk", "part.vtk"),
      surfaceCase("surface_stl_truncated", "a binary STL cut short", "gmsh's `box_binary.stl` less 10 bytes",
                  "part.stl", test::readText(dataFile("surface/box_binary.stl")).substr(0, 7958)),
      surfaceCase("surface_stl_bad_number", "an ASCII STL with a bad number", "`vertex 1 x 0`", "part.stl",
                  "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 x 0\n"),
      surfaceCase("surface_obj_index_out_of_range", "an OBJ face using a vertex it does not define",
                  "`f 1 2 9`", "part.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
      surfaceCase("surface_obj_negative_index", "an OBJ negative index past the first vertex", "`f -1 -2 -4`",
                  "part.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n"),
      surfaceCase("surface_ply_unknown_type", "a PLY property of an unknown type", "`property half y`",
                  "part.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty half y\n"),
      surfaceCase(
          "surface_ply_huge_count", "a PLY count far beyond the file size", "`element vertex 4000000000`",
          "part.ply",
          "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\nend_header\n0 1 2 3\n"),
      {"not_mesh_scene_unv", "a scene's mesh is an I-deas UNV", "`file = \"part.unv\"`",
       [](const Scratch& s) {
         s.write("part.unv", "    -1\n  2411\n         1         1         1        11\n");
         s.write("scene.toml", "[[mesh]]\nfile = \"part.unv\"\n");
       },
       "$LANCER render -q scene.toml -o out.png", nullptr},
      {"field_section_unreadable", "color_by a field whose section could not be read",
       "`color_by = { field = \"temperature\" }`, its `$NodeData` with 0 components",
       [](const Scratch& s) {
         s.copy(dataFile("reader/unreadable_nodedata_v41_ascii.msh"), "part.msh");
         s.write("scene.toml", "[[mesh]]\nfile = \"part.msh\"\ncolor_by = { field = \"temperature\" }\n");
       },
       "$LANCER render -q scene.toml -o out.png", nullptr},

      sceneCase("scene_isolines_color", "isolines colour neither a colour nor \"map\"",
                "`isolines = { field = \"T\", color = \"red\" }`",
                "[[mesh]]\nfile = \"part.msh\"\nisolines = { field = \"T\", color = \"red\" }\n"),
      {"env_step_memory", "result-step budget not a number", "`LANCER_STEP_MEMORY_MB=lots`",
       [](const Scratch& s) { s.copy(dataFile("results/cantilever.msh"), "beam.msh"); },
       "LANCER_STEP_MEMORY_MB=lots $LANCER render -q beam.msh -o out.png", nullptr},

      // --- command line, continued ---
      {"cli_unknown_subcommand", "unknown subcommand", "`lancer view part.msh`", nullptr,
       "$LANCER view part.msh", nullptr},
      {"cli_misspelt_subcommand", "misspelt subcommand", "`lancer rendr part.msh`", nullptr,
       "$LANCER rendr part.msh", nullptr},
      // --- the automatic camera's up axis ---
      sceneCase("scene_bad_up_axis", "unknown up axis", "`up_axis = \"up\"`",
                "[camera]\nup_axis = \"up\"\n[[mesh]]\nfile = \"part.msh\"\n"),
      sceneCase("scene_up_and_up_axis", "camera up given twice", "`up = [0, 0, 1]` and `up_axis = \"z\"`",
                "[camera]\nup = [0, 0, 1]\nup_axis = \"z\"\n[[mesh]]\nfile = \"part.msh\"\n"),
      {"cli_bad_up", "--up not an axis", "`--up w`", withScene(scene()),
       "$LANCER render -q --up w scene.toml -o out.png", nullptr},
      {"cli_bad_up_mesh", "--up not an axis, bare mesh", "`--up=+z part.msh`",
       [](const Scratch& s) { s.copy(dataFile("msh/square_tri3_v41_ascii.msh"), "part.msh"); },
       "$LANCER animate -q --up=+z part.msh -o out.gif", nullptr},
      // --- output encoding, tone curves, bit depth, EXR layers (docs/output.md) ---
      {"out_unknown_tonemap", "unknown tone curve", "`--tonemap agx`", withScene(scene()),
       "$LANCER render -q scene.toml --tonemap agx -o out.png", nullptr},
      {"out_exposure_nan", "exposure that is no number of stops", "`--exposure nan`", withScene(scene()),
       "$LANCER render -q scene.toml --exposure nan -o out.png", nullptr},
      {"out_bit_depth_12", "bit depth other than 8 or 16", "`--bit-depth 12`", withScene(scene()),
       "$LANCER render -q scene.toml --bit-depth 12 -o out.png", nullptr},
      {"out_bit_depth_16_bmp", "16 bits for a format without them", "`--bit-depth 16 -o out.bmp`",
       withScene(scene()), "$LANCER render -q scene.toml --bit-depth 16 -o out.bmp", nullptr},
      {"out_aovs_png", "EXR layers asked of a PNG", "`--aovs albedo -o out.png`", withScene(scene()),
       "$LANCER render -q scene.toml --aovs albedo -o out.png", nullptr},
      {"out_encoding_key", "unknown encoding in the scene", "`encoding = \"gamma\"`",
       withScene(scene("encoding = \"gamma\"\n")), "$LANCER render -q scene.toml -o out.png", nullptr},
      // --- values beyond a float ---
      {"scene_rotation_beyond_float", "environment rotation beyond a float, path tracer",
       "`rotation = 1e41`, a map",
       withMap(scene("integrator = \"path\"\n", "[environment]\nmap = \"sky.hdr\"\nrotation = 1e41\n")),
       "$LANCER render -q scene.toml -o out.png", nullptr},
      sceneCase("scene_disk_radius_underflow", "a disk light so small its area rounds to 0, path tracer",
                "`radius = 1e-30`",
                "[render]\nwidth = 16\nheight = 12\nintegrator = \"path\"\n[[light]]\ntype = \"disk\"\n"
                "position = [2, 2, 2]\nradius = 1e-30\n[[mesh]]\nfile = \"part.msh\"\n"),
      // --- sizes checked against the file before memory is taken ---
      {"map_hdr_size_beyond_file", "a 57-byte .hdr map claiming 23170x11585 pixels",
       "`map = \"sky.hdr\"`, its size line `-Y 11585 +X 23170`",
       [](const Scratch& s) {
         withScene(scene("integrator = \"path\"\n", "[environment]\nmap = \"sky.hdr\"\n"))(s);
         s.write("sky.hdr", std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 11585 +X 23170\n\x02\x02") +
                                "\x5a" + "\x82");
       },
       "$LANCER render -q scene.toml -o out.png", nullptr},
      {"map_exr_size_beyond_file", "an .exr map whose 32768x16384 header is followed by its chunk table only",
       "`map = \"sky.exr\"`, 8.6 KB",
       [](const Scratch& s) {
         withScene(scene("integrator = \"path\"\n", "[environment]\nmap = \"sky.exr\"\n"))(s);
         s.write("sky.exr", test::exrFile(
                                32768, 16384, 3, 1024, [](int, std::uint64_t start) { return start; }, ""));
       },
       "$LANCER render -q scene.toml -o out.png", nullptr},
      {"map_exr_attribute_beyond_file", "an .exr map whose header attribute says 2 GiB (30 bytes)",
       "`map = \"sky.exr\"`, an attribute of an unknown type sized 2147483647",
       [](const Scratch& s) {
         withScene(scene("integrator = \"path\"\n", "[environment]\nmap = \"sky.exr\"\n"))(s);
         s.write("sky.exr", std::string("\x76\x2f\x31\x01\x02\x00\x00\x00"
                                        "comments\0weird\0\xff\xff\xff\x7f"
                                        "abc",
                                        30));
       },
       "$LANCER render -q scene.toml -o out.png", nullptr},
      // --- text drawn into the picture, bounded when it is read ---
      {"cli_label_huge_width", "a label whose format asks for a width of 1.5 billion",
       "`--label \"{time:1500000000}\"`",
       [](const Scratch& s) { s.copy(dataFile("results/cantilever.msh"), "beam.msh"); },
       "$LANCER animate -q --over steps --label '{time:1500000000}' beam.msh -o out.gif", nullptr},
      {"scene_legend_title_too_long", "a legend title of 24,000 characters",
       "`color_by = { field = \"displacement\", title = \"TT...\" }`",
       [](const Scratch& s) {
         s.copy(dataFile("results/cantilever.msh"), "beam.msh");
         s.write("scene.toml",
                 "[[mesh]]\nfile = \"beam.msh\"\ncolor_by = { field = \"displacement\", title = \"" +
                     std::string(24000, 'T') + "\" }\n");
       },
       "$LANCER render -q scene.toml -o out.png", nullptr},
      // --- every output checked before the render ---
      {"out_legend_missing_folder", "--legend in a folder that does not exist (checked before the render)",
       "`--legend nofolder/leg.png`, existing `out.png`", withFieldScene(),
       "$LANCER render -q scene.toml -o out.png --legend nofolder/leg.png", oldOutputKept("out.png")},
      {"out_legend_bad_font", "a font that cannot be loaded, for --legend (checked before the render)",
       "`LANCER_FONT=missing.ttf`, existing `out.png`", withFieldScene(),
       "LANCER_FONT=missing.ttf $LANCER render -q scene.toml -o out.png --legend leg.png",
       oldOutputKept("out.png")},
      {"out_legend_same_path", "--legend the same file as the picture", "`--legend ./out.png -o out.png`",
       withFieldScene(), "$LANCER render -q scene.toml -o out.png --legend ./out.png",
       oldOutputKept("out.png")},
      {"cli_progressive_nan", "--progressive that is no number of seconds", "`--progressive nan`",
       withScene(scene("integrator = \"path\"\n")),
       "$LANCER render -q scene.toml --progressive nan -o out.png", nullptr},
      // --- files that are not what was asked for ---
      {"map_is_png", "a PNG image given as an environment map", "`map = \"sky.png\"` (a PNG)",
       [](const Scratch& s) {
         withScene(scene("integrator = \"path\"\n", "[environment]\nmap = \"sky.png\"\n"))(s);
         s.write("sky.png", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
       },
       "$LANCER render -q scene.toml -o out.png", nullptr},
      {"map_is_folder", "a folder given as an environment map", "`map = \"maps\"` (a folder)",
       [](const Scratch& s) {
         withScene(scene("integrator = \"path\"\n", "[environment]\nmap = \"maps\"\n"))(s);
         s.write("maps/readme.txt", "");
       },
       "$LANCER render -q scene.toml -o out.png", nullptr},
      {"font_is_folder", "a folder given as the font", "`LANCER_FONT=fonts` (a folder), `--legend leg.png`",
       [](const Scratch& s) {
         withFieldScene()(s);
         s.write("fonts/readme.txt", "");
       },
       "LANCER_FONT=fonts $LANCER render -q scene.toml -o out.png --legend leg.png",
       oldOutputKept("out.png")},
      {"opt_time_step_beyond_int", "a gmsh option beyond an int",
       "`View[0].TimeStep = 4294967296;` in `view.opt`",
       [](const Scratch& s) {
         s.copy(dataFile("results/cantilever.msh"), "beam.msh");
         s.write("view.opt", "View[0].TimeStep = 4294967296;\n");
       },
       "$LANCER render -q beam.msh --gmsh-view view.opt -o out.png", nullptr},
  };
  return cases;
}

}  // namespace lancer::bad_input
