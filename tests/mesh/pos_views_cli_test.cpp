// List-based .pos views through the built CLI: a .pos rendered and described on its own, views put
// on a mesh from the command line and from a scene file, and the commands of docs/results.md's
// section "From GetDP and gmsh's post-processing" run as written, on GetDP's and gmsh's own output
// (tests/data/pos/, tests/data/getdp/). Bad input: the message, exit code 2 and no output file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::CommandResult;
using test::contains;
using test::quoted;
using test::runCli;
using test::ScratchFolder;

std::string posFixture(const std::string& name) { return test::dataFile("pos/" + name); }

// `lancer ARGUMENTS` run in `folder` (so that relative names are the folder's).
CommandResult runCliIn(const ScratchFolder& folder, const std::string& arguments) {
  return test::runShell("cd " + quoted(folder.path().string()) + " && '" + LANCER_CLI_PATH + "' " +
                        arguments + " 2>&1");
}

// A folder holding GetDP's magnet, heat and layers results and gmsh's saved view under the names the
// docs use.
void copyResults(const ScratchFolder& folder) {
  folder.copy(posFixture("magnet/magnet.msh"), "magnet.msh");
  folder.copy(posFixture("magnet/az.pos"), "az.pos");
  folder.copy(posFixture("magnet/b_a.pos"), "b_a.pos");
  folder.copy(posFixture("heat/heat.msh"), "heat.msh");
  folder.copy(posFixture("heat/t.pos"), "t.pos");
  folder.copy(posFixture("heat/steps.pos"), "steps.pos");
  folder.copy(posFixture("layers/layers.msh"), "layers.msh");  // a volume mesh, views on its volumes
  folder.copy(posFixture("layers/v.pos"), "v.pos");
  folder.copy(posFixture("layers/e.pos"), "e.pos");
  folder.copy(posFixture("gmsh_lists.pos"), "view.pos");  // written by gmsh.view.write, Save View's writer
  std::filesystem::create_directory(folder.path() / "v2");
  folder.copy(test::dataFile("getdp/magnet_v2_az.pos"), "v2/az.pos");
  folder.copy(test::dataFile("getdp/magnet_v2_b.pos"), "v2/b_a.pos");
}

// Exit code 2, every part in the message, and the folder as it was (no output file).
void expectRefused(const ScratchFolder& folder, const std::string& arguments,
                   std::initializer_list<std::string_view> parts) {
  const std::vector<std::string> before = folder.entriesBelow();
  const CommandResult result = runCliIn(folder, arguments);
  EXPECT_EQ(result.exitCode, 2) << result.output;
  test::expectContainsAll(result.output, parts);
  EXPECT_EQ(folder.entriesBelow(), before) << arguments;
}

TEST(PosViewsCli, AViewRendersAndIsDescribedOnItsOwn) {
  ScratchFolder folder;
  copyResults(folder);
  const CommandResult render =
      runCliIn(folder, "render -q az.pos --color-by az --width 64 --height 48 -o az.png");
  ASSERT_EQ(render.exitCode, 0) << render.output;
  EXPECT_TRUE(std::filesystem::exists(folder.file("az.png")));
  const CommandResult info = runCliIn(folder, "info az.pos");
  ASSERT_EQ(info.exitCode, 0) << info.output;
  test::expectContainsAll(info.output,
                          {"format:          list-based views (.pos, gmsh's parsed post-processing format)",
                           "nodes:           159", "279  3-node triangle (type 2)",
                           "faces rendered:  279 (279 triangles, 0 quads)",
                           "\"az\"                     element-node data, 1 component, step 0 (time 0)"});
  const CommandResult json = runCliIn(folder, "info --json az.pos");
  ASSERT_EQ(json.exitCode, 0) << json.output;
  EXPECT_TRUE(contains(json.output, "\"format\": \"pos\"")) << json.output;
}

TEST(PosViewsCli, InfoListsTheTransientStepsAndTheirTimes) {
  ScratchFolder folder;
  copyResults(folder);
  const CommandResult info = runCliIn(folder, "info t.pos");
  ASSERT_EQ(info.exitCode, 0) << info.output;
  test::expectContainsAll(
      info.output, {"\"T\"                      element-node data, 1 component, step 0 (time 0),",
                    "\"T\"                      element-node data, 1 component, step 1 (time 0.01),",
                    "\"T\"                      element-node data, 1 component, step 2 (time 0.02),",
                    "\"T\"                      element-node data, 1 component, step 3 (time 0.03),",
                    "\"gradT\"                  element-node data, 3 components, step 3 (time 0.03),"});
}

TEST(PosViewsCli, ViewsOfDifferentStepCountsOnOneMesh) {
  ScratchFolder folder;
  copyResults(folder);
  // heat.msh with t.pos (T and gradT, 4 steps each) and steps.pos (3 more steps of T, no TIME list).
  const CommandResult info = runCliIn(folder, "info heat.msh t.pos steps.pos");
  ASSERT_EQ(info.exitCode, 0) << info.output;
  test::expectContainsAll(
      info.output, {"\"T\"                      element-node data, 1 component, step 3 (time 0.03),",
                    "\"T\"                      element-node data, 1 component, step 6 (time 6),",
                    "\"gradT\"                  element-node data, 3 components, step 3 (time 0.03),"});
  EXPECT_FALSE(contains(info.output, "\"gradT\"                  element-node data, 3 components, step 4"));
  const CommandResult render = runCliIn(
      folder, "render -q heat.msh t.pos steps.pos --color-by T --step 5 --width 48 --height 32 -o t5.png");
  EXPECT_EQ(render.exitCode, 0) << render.output;
  expectRefused(folder, "render -q heat.msh t.pos steps.pos --color-by gradT --step 5 -o g5.png",
                {"--color-by: error: color_by field \"gradT\" has no step 5: its steps are 0, 1, 2, 3",
                 "it has \"T\" (steps 0 to 6), \"gradT\" (steps 0, 1, 2, 3)"});
}

TEST(PosViewsCli, ViewsGoOnAMeshFromAScene) {
  ScratchFolder folder;
  copyResults(folder);
  folder.write("results/magnet.toml",
               "[render]\nwidth = 64\nheight = 48\n[[mesh]]\nfile = \"../magnet.msh\"\n"
               "views = [\"../az.pos\", \"../b_a.pos\"]\ncolor_by = { field = \"b\" }\n");
  const CommandResult render = runCliIn(folder, "render -q results/magnet.toml -o b.png");
  ASSERT_EQ(render.exitCode, 0) << render.output;
  folder.write("bad.toml", "[[mesh]]\nfile = \"magnet.msh\"\nviews = \"az.pos\"\n");
  expectRefused(folder, "render -q bad.toml -o x.png",
                {"bad.toml:3:9: error: mesh[0].views must be an array of file names, views = [\"az.pos\", "
                 "\"b.pos\"] (list-based .pos views, relative to the scene file); found string \"az.pos\""});
  folder.write("missing.toml", "[[mesh]]\nfile = \"magnet.msh\"\nviews = [\"bz.pos\"]\n");
  expectRefused(folder, "render -q missing.toml -o x.png",
                {"missing.toml:1:1: error: view file '", "bz.pos' does not exist"});
}

TEST(PosViewsCli, BadInputsSayWhatIsWrong) {
  ScratchFolder folder;
  copyResults(folder);
  expectRefused(folder, "render -q magnet.msh t.pos --color-by T -o x.png",
                {"t.pos:1: error: view \"T\" matches no face of magnet.msh: none of its 33 elements",
                 "give the mesh the view was computed on (the .msh the solver read), or draw the view on its "
                 "own elements: lancer render t.pos"});
  expectRefused(
      folder, "render -q magnet.msh az.pos heat.msh -o x.png",
      {"heat.msh: error: one mesh or scene per command: magnet.msh gives the geometry, and the inputs "
       "after it are list-based .pos views to put on it, which this is not"});
  folder.write("scene.toml", "[[mesh]]\nfile = \"magnet.msh\"\n");
  expectRefused(
      folder, "render -q scene.toml az.pos -o x.png",
      {"az.pos: error: views on the command line go on a mesh given there (lancer render part.msh "
       "az.pos); scene.toml is a scene file: give them to its mesh with views = [\"az.pos\"] in its "
       "[[mesh]]"});
  folder.write(
      "mixed.pos",
      "View \"m\" {\nST(0,0,0,1,0,0,0,1,0){1,2,3};\nVT(1,0,0,1,1,0,0,1,0){1,0,0,1,0,0,1,0,0};\n};\n");
  expectRefused(folder, "render -q mixed.pos -o x.png",
                {"mixed.pos:1: error: view \"m\" holds scalar elements (ST at line 2) and vector elements"});
  folder.copy(posFixture("binary_view.pos"), "old.pos");
  expectRefused(
      folder, "render -q magnet.msh old.pos -o x.png",
      {"old.pos:1:1: error: this is a view in gmsh's older post-processing format ($PostFormat, binary"});
  expectRefused(folder, "render -q magnet.msh az.pos bz.pos -o x.png",
                {"bz.pos: error: cannot open the view file: No such file or directory"});
  expectRefused(folder, "render -q magnet.msh v2/az.pos -o x.png",
                {"v2/az.pos: error: one mesh or scene per command"});
}

// The section of docs/results.md on GetDP and gmsh, its fenced blocks: ```sh lines that start
// with `lancer ` are commands; the ```toml block is magnet.toml.
struct DocSection {
  std::vector<std::string> commands;
  std::string scene;
};
DocSection readDocSection() {
  std::istringstream page(test::readText(std::string(LANCER_SOURCE_DIR) + "/docs/results.md"));
  DocSection section;
  std::string line, fence;
  bool inSection = false;
  while (std::getline(page, line)) {
    if (line.starts_with("## ")) inSection = line == "## From GetDP and gmsh's post-processing";
    if (!inSection) continue;
    if (line.starts_with("```")) {
      fence = fence.empty() ? line.substr(3) : "";
      continue;
    }
    if (fence == "sh" && line.starts_with("lancer "))  // without its comment
      section.commands.push_back(line.substr(7, line.find(" #") - 7));
    if (fence == "toml") section.scene += line + "\n";
  }
  return section;
}

TEST(PosViewsCli, TheCommandsOfTheDocsSectionRunAsWritten) {
  const DocSection section = readDocSection();
  ASSERT_GE(section.commands.size(), 9u) << "docs/results.md lost its GetDP section's commands";
  ASSERT_FALSE(section.scene.empty());
  ScratchFolder folder;
  copyResults(folder);
  folder.write("magnet.toml", section.scene);
  static const std::regex kOutput(R"(-o (\S+))");
  for (const std::string& command : section.commands) {
    SCOPED_TRACE(command);
    const CommandResult result = runCliIn(folder, command);
    EXPECT_EQ(result.exitCode, 0) << result.output;
    std::smatch output;
    if (std::regex_search(command, output, kOutput)) {
      EXPECT_TRUE(std::filesystem::exists(folder.file(output[1]))) << output[1];
    }
  }
}

}  // namespace
}  // namespace lancer
