// Slices, coloured cut caps and isosurfaces as a user asks for them (scene files and the CLI), on the
// gmsh-made cube of tetrahedra whose field f = x + 2y + 3z is linear (tests/data/element_node): at
// every pixel of a slice seen straight on, unlit, the colour is the map's at f of the point the
// pixel sees; a cap of a coloured mesh is the same slice; requests the volume cannot meet exit 2.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli.hpp"
#include "support/files.hpp"
#include "support/slice_colours.hpp"

namespace lancer {
namespace {

constexpr int kSide = 96;

std::string cube() { return test::dataFile("element_node/tet_v41_bin.msh"); }

// Straight down at z = 0.3 of the unit cube (support/slice_colours.hpp); `mesh` holds the rest of
// the [[mesh]] table and what follows it.
std::string topViewScene(const std::string& mesh) {
  return test::topViewSliceScene(kSide, fmt::format("file = \"{}\"", cube()), mesh);
}

TEST(VolumeViews, ASliceSeenStraightOnShowsTheFieldAtEveryPixel) {
  const test::ScratchFolder folder;
  const int checked = test::expectSliceColours(
      folder, topViewScene("skin = \"hidden\"\n\n[[mesh.slice]]\npoint = [0, 0, 0.3]\nnormal = [0, 0, 1]\n"));
  EXPECT_GT(checked, kSide * kSide / 2);
}

TEST(VolumeViews, ACutCapOfAColouredVolumeShowsTheField) {
  // The top of the cube cut away at z = 0.3: the cap is the slice there.
  const test::ScratchFolder folder;
  const int checked =
      test::expectSliceColours(folder, topViewScene("\n[[clip]]\npoint = [0, 0, 0.3]\nnormal = [0, 0, 1]\n"));
  EXPECT_GT(checked, kSide * kSide / 2);
}

TEST(VolumeViews, TheCliDrawsSlicesAndIsosurfaces) {
  const test::ScratchFolder folder;
  const std::string out = folder.file("out.png");
  for (const std::string options :
       {"--color-by f --slice z=0.3 --slice x", "--color-by f --slice 0.5,0.5,0.5,1,1,0 --skin edges",
        "--isosurfaces f:3", "--isosurfaces f --isovalues 1,2.5 --color-by g",
        "--color-by f --clip y=0.5 --legend right",
        // Every kind on one mesh: each adds a mesh to the scene after the others.
        "--color-by f --slice z --slice x --isosurfaces f:2 --streamlines u:3 --clip y=0.5"}) {
    const test::CommandResult run =
        test::runCli("render " + test::quoted(cube()) + " " + options + " --width 64 --height 48 -q -o " +
                     test::quoted(out) + " 2>&1");
    EXPECT_EQ(run.exitCode, 0) << options << "\n" << run.output;
  }
}

TEST(VolumeViews, RequestsTheVolumeCannotMeetExitTwoWithoutAPicture) {
  const test::ScratchFolder folder;
  const std::string out = folder.file("out.png");
  const std::string surface = test::dataFile("element_node/quad9_v41_bin.msh");
  const struct {
    std::string input, options, message;
  } cases[] = {
      {surface, "--color-by f --slice z=0", "has no volume elements"},
      {cube(), "--isosurfaces u", "it has 3 components"},
      {cube(), "--isosurfaces nope",
       "has no such field inside its volume (its fields: f, g, jump, jumpe, u)"},
      {cube(), "--isovalues 1,2", "--isovalues gives the values of --isosurfaces FIELD"},
      {cube(), "--isosurfaces f:0", "COUNT is a whole number from 1 to 100"},
      {cube(), "--isosurfaces f --isovalues 1,x", "is not a list of up to 100 finite numbers"},
      {cube(), "--slice w=1", "is not a plane"},
      {cube(), "--slice 0,0,0,0,0,0", "a normal other than [0, 0, 0]"},
      {cube(), "--skin glass --slice z", "is not a skin style"},
  };
  for (const auto& c : cases) {
    const test::CommandResult run =
        test::runCli("render " + test::quoted(c.input) + " " + c.options + " --width 32 --height 32 -q -o " +
                     test::quoted(out) + " 2>&1");
    EXPECT_EQ(run.exitCode, 2) << c.options << "\n" << run.output;
    EXPECT_TRUE(test::contains(run.output, c.message)) << c.options << "\n" << run.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.options;
  }
}

TEST(VolumeViews, NotesForASliceThatMissesAndValuesOutsideTheRange) {
  const test::ScratchFolder folder;
  const std::string out = folder.file("out.png");
  const test::CommandResult run = test::runCli("render " + test::quoted(cube()) +
                                               " --color-by f --slice z=7 --isosurfaces f --isovalues 3,99" +
                                               " --width 32 --height 32 -o " + test::quoted(out) + " 2>&1");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_TRUE(test::contains(run.output, "misses the volume")) << run.output;
  EXPECT_TRUE(test::contains(run.output, "99 outside its range")) << run.output;
}

TEST(VolumeViews, SceneFileKeysAreChecked) {
  const test::ScratchFolder folder;
  const std::string path = folder.file("scene.toml");
  const struct {
    std::string mesh, message;
  } cases[] = {
      {"\n[[mesh.slice]]\npoint = [0, 0, 0.3]\n", "normal"},
      {"\n[[mesh.slice]]\nnormal = [0, 0, 1]\nponit = [0, 0, 0]\n", "did you mean 'point'"},
      {"skin = \"glass\"\n", "skin"},
      {"isosurfaces = { field = \"f\", count = 3, values = [1] }\n", "gives both count and values"},
      {"isosurfaces = { field = \"f\", color = [1, 0, 0], color_by = \"g\" }\n",
       "gives both color and color_by"},
      {"isosurfaces = { count = 3 }\n", "field"},
      {"isosurfaces = { field = \"f\", values = [1e39] }\n", "finite numbers"},
      {"streamlines = { field = \"f\" }\n", "field lines follow a vector (3 components)"},
      {"streamlines = { field = \"u\", seed_line = [[0, 0, 0], [1, 1, 1]], seed_points = [[0.5, 0.5, 0.5]] "
       "}\n",
       "gives seeds more than one way"},
      {"streamlines = { field = \"u\", seed_center = [0.5, 0.5, 0.5] }\n", "a disk of seeds needs"},
      {"streamlines = { field = \"u\", seed_points = [[5, 5, 5]] }\n",
       "none of the 1 seeds is inside the volume"},
      {"streamlines = { field = \"u\", seed_line = [[0, 0, 0]] }\n", "must be an array of 2 points"},
      {"streamlines = { field = \"u\", direction = \"up\" }\n", "direction"},
  };
  for (const auto& c : cases) {
    std::ofstream(path) << topViewScene(c.mesh);
    const test::CommandResult run = test::runCli("render " + test::quoted(path) + " -q -o " +
                                                 test::quoted(folder.file("out.png")) + " 2>&1");
    EXPECT_EQ(run.exitCode, 2) << c.mesh << "\n" << run.output;
    EXPECT_TRUE(test::contains(run.output, c.message)) << c.mesh << "\n" << run.output;
  }
}

TEST(VolumeViews, FieldLinesFromEverySeedKindRender) {
  const test::ScratchFolder folder;
  const std::string path = folder.file("scene.toml");
  for (const std::string lines : {"streamlines = { field = \"u\", count = 5 }",
                                  "streamlines = { field = \"u\", seed_points = [[0.5, 0.5, 0.5]] }",
                                  "streamlines = { field = \"u\", seed_line = [[0.1, 0.1, 0.5], [0.9, 0.9, "
                                  "0.5]], count = 4, color = [1, 0, 0] }",
                                  "streamlines = { field = \"u\", seed_center = [0.5, 0.5, 0.5], seed_radius "
                                  "= 0.2, count = 6, color_by = \"f\" }"}) {
    std::ofstream(path) << topViewScene(lines + "\nskin = \"edges\"\n");
    const test::CommandResult run = test::runCli("render " + test::quoted(path) + " -q -o " +
                                                 test::quoted(folder.file("out.png")) + " 2>&1");
    EXPECT_EQ(run.exitCode, 0) << lines << "\n" << run.output;
  }
  const test::CommandResult cli =
      test::runCli("render " + test::quoted(cube()) +
                   " --streamlines u:3 --seed-line 0.1,0.1,0.5,0.9,0.9,0.5 --width 32 "
                   "--height 24 -q -o " +
                   test::quoted(folder.file("cli.png")) + " 2>&1");
  EXPECT_EQ(cli.exitCode, 0) << cli.output;
  const test::CommandResult bad =
      test::runCli("render " + test::quoted(cube()) + " --seed-line 0,0,0,1,1,1 -o " +
                   test::quoted(folder.file("bad.png")) + " 2>&1");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_TRUE(test::contains(bad.output, "add --streamlines")) << bad.output;
}

TEST(VolumeProbeCli, PrintsTheFieldAndSaysWhatIsWrong) {
  const test::CommandResult run =
      test::runCli("probe " + test::quoted(cube()) + " --at 0.1,0.2,0.3 --field f 2>&1");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_TRUE(test::contains(run.output, "f at (0.1, 0.2, 0.3), step 0 (t = 0): 1.3999")) << run.output;
  const test::CommandResult json =
      test::runCli("probe " + test::quoted(cube()) + " --at 0.5,0.5,0.5 --field u --json 2>&1");
  EXPECT_EQ(json.exitCode, 0) << json.output;
  EXPECT_TRUE(test::contains(json.output, "\"field\": \"u\", \"at\": \"element-node\"")) << json.output;
  for (const std::string bad : {"--at 2,0,0", "--at 0.5,0.5", "--at 0.5,0.5,0.5 --field nope",
                                "--at 0.5,0.5,0.5 --field g --step 5"}) {
    const test::CommandResult failed = test::runCli("probe " + test::quoted(cube()) + " " + bad + " 2>&1");
    EXPECT_EQ(failed.exitCode, 2) << bad << "\n" << failed.output;
  }
  const test::CommandResult surface = test::runCli(
      "probe " + test::quoted(test::dataFile("element_node/quad9_v41_bin.msh")) + " --at 0,0,0 2>&1");
  EXPECT_EQ(surface.exitCode, 2);
  EXPECT_TRUE(test::contains(surface.output, "has no volume elements")) << surface.output;
}

}  // namespace
}  // namespace lancer
