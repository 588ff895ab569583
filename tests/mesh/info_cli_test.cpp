// `lancer info` through the built CLI: text and --json output for a fixture, and exit code 2 with a
// one-line compiler-style message for a broken file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::CommandResult;
using test::contains;
using test::runCli;

// Runs `lancer info ARGUMENTS` on a file that reads, and checks that the report holds every one of `parts`.
void expectInfoSays(const std::string& arguments, std::initializer_list<std::string_view> parts) {
  const CommandResult result = runCli("info " + arguments);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  test::expectContainsAll(result.output, parts);
}

TEST(InfoCli, TextReport) {
  expectInfoSays(test::quoted(test::mshFixture("square_tri6_v41_bin.msh")),
                 {
                     "format:          MSH 4.1 binary",
                     "nodes:           81",
                     "32  6-node triangle (type 9)",
                     "16  3-node line (type 8)",
                     "faces rendered:  128 (128 triangles, 0 quads)",
                     "dim 2 tag 1      \"plate\"                  128 faces",
                     "bounding box:    [0, 0, 0] .. [1, 1, 0]",
                     "surface area:    1\n",
                     "shells:          1 (0 closed, 0 closed and consistently oriented)",
                     "load time:",
                 });
}

TEST(InfoCli, TextReportOfAClosedSkinAndUnrenderableElements) {
  expectInfoSays(test::quoted(test::mshFixture("cube_hex8_v22_bin.msh")),
                 {"volume skin:     54 faces from 27 volume elements",
                  "closed, consistently oriented (normals point outward, volume 1)"});
  const CommandResult cubic = runCli("info '" + test::mshFixture("square_tri10_v41_ascii.msh") + "'");
  ASSERT_EQ(cubic.exitCode, 0) << cubic.output;
  test::expectContainsAll(
      cubic.output,
      {"          32  10-node triangle (type 21): split into flat faces through all its nodes\n",
       "faces rendered:  288 (288 triangles, 0 quads)"});
  EXPECT_FALSE(contains(cubic.output, "not rendered:")) << cubic.output;
}

// Sections the reader reads past are named with why nothing of them is drawn: a file's
// $InterpolationScheme (which its element data names) is not dropped without a word.
TEST(InfoCli, NamesTheSectionsItSkipped) {
  const std::string path = test::quoted(test::mshFixture("elementdata_v41_ascii.msh"));
  expectInfoSays(path, {"sections skipped:\n",
                        "           1  $InterpolationScheme: interpolation matrices; fields are drawn from "
                        "their values at the element corners\n",
                        "           1  $Periodic: periodic node links"});
  expectInfoSays("--json " + path, {"\"skippedSections\": {\"$InterpolationScheme\": 1, \"$Periodic\": 1},"});
  const CommandResult plain = runCli("info " + test::quoted(test::mshFixture("cube_hex8_v22_bin.msh")));
  EXPECT_FALSE(contains(plain.output, "sections skipped")) << plain.output;
}

TEST(InfoCli, JsonReport) {
  const CommandResult result = runCli("info --json '" + test::mshFixture("square_quad4_v22_ascii.msh") + "'");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const std::string& out = result.output;
  EXPECT_EQ(out.front(), '{');
  test::expectContainsAll(
      out,
      {
          "\"version\": \"2.2\",\n  \"binary\": false,",
          "\"nodes\": 25,",
          "\"elementsByType\": {\"1\": 16, \"3\": 16},",
          "\"faces\": {\"total\": 16, \"triangles\": 0, \"quads\": 16},",
          // gmsh writes each quad once per physical group ("plate", "everything"): 16 second copies skipped.
          "\"duplicateElementsSkipped\": 16,",
          "{\"dimension\": 2, \"tag\": 1, \"name\": \"plate\", \"faces\": 16, \"interfaceFaces\": 0}",
          "\"boundingBox\": {\"min\": [0, 0, 0], \"max\": [1, 1, 0]},",
          "\"area\": 1,",
          "\"closed\": false, \"consistentlyOriented\": true",
          "\"loadSeconds\": ",
      });
}

TEST(InfoCli, BrokenFileExitsWithCodeTwoAndOneLine) {
  const std::string path = test::mshFixture("broken/missing_node_v41.msh");
  const CommandResult result = runCli("info '" + path + "'");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_EQ(
      result.output,
      path + ":107:1: error: element 17 (3-node triangle) uses node 9001, which $Nodes does not define\n");
}

TEST(InfoCli, DirectoryExitsWithCodeTwo) {
  const std::string path = test::mshFixture("broken");
  const CommandResult result = runCli("info '" + path + "'");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_EQ(result.output, path + ": error: is a directory, not a .msh file\n");
}

TEST(InfoCli, MissingFileExitsWithCodeTwo) {
  const CommandResult result = runCli("info /nonexistent/part.msh");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_EQ(result.output, "/nonexistent/part.msh: error: cannot open the file: No such file or directory\n");
}

TEST(InfoCli, CavityWallIsReportedAsSuch) {
  // gmsh's hollow sphere: the tetrahedra's skin faces out of the material, into the cavity inside.
  const std::string path = test::dataFile("render/hollow_sphere.msh");
  expectInfoSays(test::quoted(path), {"shells:          2 (2 closed, 2 closed and consistently oriented)",
                                      "(normals point outward, volume ",
                                      "(cavity wall, normals point into the cavity, volume 0."});
  expectInfoSays("--json " + test::quoted(path),
                 {", \"cavity\": true, \"interface\": false}", ", \"cavity\": false, \"interface\": false}"});
}

TEST(InfoCli, VolumesListTheirSkinAndInterfaceFacesAndNameTheInterfaces) {
  // tests/data/multimaterial/three_materials.geo: housing around bushing around shaft, meshed together.
  const std::string path = test::dataFile("multimaterial/three_materials_v41.msh");
  expectInfoSays(test::quoted(path), {
                                         "interfaces:      1004 faces shared by two volumes",
                                         "\"Housing\"                2618 faces (1980 skin, 638 interface)\n",
                                         "\"Bushing\"                1342 faces (338 skin, 1004 interface)\n",
                                         "\"Shaft\"                  722 faces (356 skin, 366 interface)\n",
                                         "  interface \"Housing\" (1) | \"Bushing\" (2): 638 faces\n",
                                         "  interface \"Bushing\" (2) | \"Shaft\" (3): 366 faces\n",
                                     });
  expectInfoSays("--json " + test::quoted(path),
                 {"\"name\": \"Bushing\", \"faces\": 1342, \"interfaceFaces\": 1004}",
                  "\"interfaceFaces\": 1004,\n  \"interfaces\": [\n    {\"tags\": [1, 2], "
                  "\"entities\": [0, 0], \"names\": [\"Housing\", \"Bushing\"], \"faces\": 638},\n    "
                  "{\"tags\": [2, 3], "
                  "\"entities\": [0, 0], \"names\": [\"Bushing\", \"Shaft\"], \"faces\": 366}\n  ],"});
}

// render and animate say what info says about a mesh: faces dropped as degenerate (and element types
// not drawn), each once, naming the file.
TEST(InfoCli, RenderAndAnimatePrintTheMeshWarningsInfoPrints) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "lancer_info_cli_warnings";
  std::filesystem::create_directories(folder);
  const std::string mesh = (folder / "degenerate.msh").string();
  std::ofstream(mesh) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n"
                         "1 0 0 0\n2 1 0 0\n3 2 0 0\n4 0 1 0\n$EndNodes\n"
                         "$Elements\n3\n1 2 2 0 1 1 2 4\n2 2 2 0 1 1 2 3\n3 2 2 0 1 1 1 4\n$EndElements\n";
  const std::string warning = mesh + ": warning: 2 degenerate (zero-area) faces dropped\n";
  for (const std::string& command :
       {"info '" + mesh + "'", "render '" + mesh + "' -o '" + (folder / "out.png").string() + "'",
        "animate --frames 2 '" + mesh + "' -o '" + (folder / "out.gif").string() + "'"}) {
    const CommandResult result = runCli(command);
    EXPECT_EQ(result.exitCode, 0) << command << "\n" << result.output;
    const std::size_t at = result.output.find(warning);
    EXPECT_NE(at, std::string::npos) << command << "\n" << result.output;
    EXPECT_EQ(result.output.find(warning, at + 1), std::string::npos) << command << "\n" << result.output;
  }
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace lancer
