// `lancer info` through the built CLI: text and --json output for a fixture, and exit code 2 with a
// one-line compiler-style message for a broken file.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "mesh/msh_test_util.hpp"

namespace lancer {
namespace {

struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

CommandResult runCli(const std::string& arguments) {
  const std::string command = std::string("'") + LANCER_CLI_PATH + "' " + arguments + " 2>&1";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  std::size_t got;
  while ((got = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, got);
  const int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(InfoCli, TextReport) {
  const CommandResult result = runCli("info '" + test::mshFixture("square_tri6_v41_bin.msh") + "'");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const std::string& out = result.output;
  EXPECT_TRUE(contains(out, "format:          MSH 4.1 binary")) << out;
  EXPECT_TRUE(contains(out, "nodes:           81")) << out;
  EXPECT_TRUE(contains(out, "32  6-node triangle (type 9)")) << out;
  EXPECT_TRUE(contains(out, "16  3-node line (type 8)")) << out;
  EXPECT_TRUE(contains(out, "faces rendered:  128 (128 triangles, 0 quads)")) << out;
  EXPECT_TRUE(contains(out, "dim 2 tag 1      \"plate\"                  128 faces")) << out;
  EXPECT_TRUE(contains(out, "bounding box:    [0, 0, 0] .. [1, 1, 0]")) << out;
  EXPECT_TRUE(contains(out, "surface area:    1\n")) << out;
  EXPECT_TRUE(contains(out, "shells:          1 (0 closed, 0 closed and consistently oriented)")) << out;
  EXPECT_TRUE(contains(out, "load time:")) << out;
}

TEST(InfoCli, TextReportOfAClosedSkinAndUnrenderableElements) {
  const CommandResult skin = runCli("info '" + test::mshFixture("cube_hex8_v22_bin.msh") + "'");
  ASSERT_EQ(skin.exitCode, 0) << skin.output;
  EXPECT_TRUE(contains(skin.output, "volume skin:     54 faces from 27 volume elements")) << skin.output;
  EXPECT_TRUE(contains(skin.output, "closed, consistently oriented (normals point outward, volume 1)"))
      << skin.output;
  const CommandResult cubic = runCli("info '" + test::mshFixture("square_tri10_v41_ascii.msh") + "'");
  ASSERT_EQ(cubic.exitCode, 0) << cubic.output;
  EXPECT_TRUE(contains(cubic.output,
                       "          32  10-node triangle (type 21): split into flat faces through all its nodes\n"))
      << cubic.output;
  EXPECT_TRUE(contains(cubic.output, "faces rendered:  288 (288 triangles, 0 quads)")) << cubic.output;
  EXPECT_FALSE(contains(cubic.output, "not rendered:")) << cubic.output;
}

TEST(InfoCli, JsonReport) {
  const CommandResult result = runCli("info --json '" + test::mshFixture("square_quad4_v22_ascii.msh") + "'");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const std::string& out = result.output;
  EXPECT_EQ(out.front(), '{');
  EXPECT_TRUE(contains(out, "\"version\": \"2.2\",\n  \"binary\": false,")) << out;
  EXPECT_TRUE(contains(out, "\"nodes\": 25,")) << out;
  EXPECT_TRUE(contains(out, "\"elementsByType\": {\"1\": 16, \"3\": 16},")) << out;
  EXPECT_TRUE(contains(out, "\"faces\": {\"total\": 16, \"triangles\": 0, \"quads\": 16},")) << out;
  // gmsh writes each quad once per physical group ("plate", "everything"): 16 second copies skipped.
  EXPECT_TRUE(contains(out, "\"duplicateElementsSkipped\": 16,")) << out;
  EXPECT_TRUE(contains(out, "{\"dimension\": 2, \"tag\": 1, \"name\": \"plate\", \"faces\": 16, \"interfaceFaces\": 0}")) << out;
  EXPECT_TRUE(contains(out, "\"boundingBox\": {\"min\": [0, 0, 0], \"max\": [1, 1, 0]},")) << out;
  EXPECT_TRUE(contains(out, "\"area\": 1,")) << out;
  EXPECT_TRUE(contains(out, "\"closed\": false, \"consistentlyOriented\": true")) << out;
  EXPECT_TRUE(contains(out, "\"loadSeconds\": ")) << out;
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
  const std::string path = std::string(LANCER_TEST_DATA_DIR) + "/render/hollow_sphere.msh";
  const CommandResult text = runCli("info '" + path + "'");
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_TRUE(contains(text.output, "shells:          2 (2 closed, 2 closed and consistently oriented)"))
      << text.output;
  EXPECT_TRUE(contains(text.output, "(normals point outward, volume ")) << text.output;
  EXPECT_TRUE(contains(text.output, "(cavity wall, normals point into the cavity, volume 0.")) << text.output;
  const CommandResult json = runCli("info --json '" + path + "'");
  ASSERT_EQ(json.exitCode, 0) << json.output;
  EXPECT_TRUE(contains(json.output, ", \"cavity\": true, \"interface\": false}")) << json.output;
  EXPECT_TRUE(contains(json.output, ", \"cavity\": false, \"interface\": false}")) << json.output;
}

TEST(InfoCli, VolumesListTheirSkinAndInterfaceFacesAndNameTheInterfaces) {
  // tests/data/multimaterial/three_materials.geo: housing around bushing around shaft, meshed together.
  const std::string path = std::string(LANCER_TEST_DATA_DIR) + "/multimaterial/three_materials_v41.msh";
  const CommandResult text = runCli("info '" + path + "'");
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_TRUE(contains(text.output, "interfaces:      1004 faces shared by two volumes")) << text.output;
  EXPECT_TRUE(contains(text.output, "\"Housing\"                2618 faces (1980 skin, 638 interface)\n"))
      << text.output;
  EXPECT_TRUE(contains(text.output, "\"Bushing\"                1342 faces (338 skin, 1004 interface)\n"))
      << text.output;
  EXPECT_TRUE(contains(text.output, "\"Shaft\"                  722 faces (356 skin, 366 interface)\n"))
      << text.output;
  EXPECT_TRUE(contains(text.output, "  interface \"Housing\" (1) | \"Bushing\" (2): 638 faces\n")) << text.output;
  EXPECT_TRUE(contains(text.output, "  interface \"Bushing\" (2) | \"Shaft\" (3): 366 faces\n")) << text.output;
  const CommandResult json = runCli("info --json '" + path + "'");
  ASSERT_EQ(json.exitCode, 0) << json.output;
  EXPECT_TRUE(contains(json.output, "\"name\": \"Bushing\", \"faces\": 1342, \"interfaceFaces\": 1004}"))
      << json.output;
  EXPECT_TRUE(contains(json.output, "\"interfaceFaces\": 1004,\n  \"interfaces\": [\n    {\"tags\": [1, 2], "
                                    "\"entities\": [0, 0], \"names\": [\"Housing\", \"Bushing\"], \"faces\": 638},\n    {\"tags\": [2, 3], "
                                    "\"entities\": [0, 0], \"names\": [\"Bushing\", \"Shaft\"], \"faces\": 366}\n  ],"))
      << json.output;
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
