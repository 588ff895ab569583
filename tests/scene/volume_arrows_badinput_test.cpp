// Bad requests of arrows through the volume: a grid of 0 or of more points than a mesh may have
// arrows (refused before anything is allocated), grid with max_count, a scalar field, a field or step
// the volume lacks, a mesh without volume elements; the scene key, the CLI and its exit code.
#include <gtest/gtest.h>

#include <string>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/results/arrows.hpp"
#include "lancer/scene/results/volume_arrows.hpp"
#include "lancer/scene/scene.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

std::string withArrows(const std::string& arrows) {
  return "[[mesh]]\nfile = \"a.msh\"\narrows = { field = \"u\", " + arrows + " }\n";
}

TEST(VolumeArrowsBadInput, GridKey) {
  test::expectSceneErrorContains(
      withArrows("grid = [0, 4, 4]"),
      "mesh[0].arrows.grid[0] must be an integer from 1 to 100000, found integer 0");
  test::expectSceneErrorContains(withArrows("grid = [4, 4]"),
                                 "mesh[0].arrows.grid must be an array of three integers [nx, ny, nz]");
  test::expectSceneErrorContains(withArrows("grid = 8"), "found integer 8");
  test::expectSceneErrorContains(withArrows("grid = [4, 4.5, 4]"), "mesh[0].arrows.grid[1]");
  // 10^15 points: refused by their count, not by the memory they would take.
  test::expectSceneErrorContains(withArrows("grid = [100000, 100000, 100000]"),
                                 "mesh[0].arrows.grid asks for 100000 x 100000 x 100000 = 1000000000000000 "
                                 "points, more than the 100000 arrows a mesh may have");
  test::expectSceneErrorContains(
      withArrows("grid = [4, 4, 4], max_count = 10"),
      "give max_count for arrows on the surface, or grid for arrows through the volume");
}

TEST(VolumeArrowsBadInput, FieldsTheVolumeCannotDraw) {
  const MeshWithVolume read = readMshWithVolume(test::dataFile("volume/cube_hex.msh"));
  ArrowSpec spec;
  spec.grid = std::array<int, 3>{2, 2, 2};
  spec.where = SourceLocation{"scene.toml", 3, 10};
  spec.field = "f";
  EXPECT_EQ(test::messageOf([&] { volumeArrowMesh(spec, *read.volume, {}, "cube_hex.msh"); }),
            "scene.toml:3:10: error: arrows field \"f\" must be a vector of 3 components (node, element or "
            "element-node data), but it is node data of 1 component");
  spec.field = "g";  // element data
  EXPECT_NE(test::messageOf([&] {
              volumeArrowMesh(spec, *read.volume, {}, "cube_hex.msh");
            }).find("but it is element data of 1 component"),
            std::string::npos);
  spec.field = "velocity";
  EXPECT_EQ(test::messageOf([&] { volumeArrowMesh(spec, *read.volume, {}, "cube_hex.msh"); }),
            "scene.toml:3:10: error: arrows field \"velocity\" is not given inside the volume of "
            "'cube_hex.msh' (its fields: f, u, dipole, g)");
  spec.field = "u";
  spec.step = 7;
  EXPECT_NE(test::messageOf([&] {
              volumeArrowMesh(spec, *read.volume, {}, "cube_hex.msh");
            }).find("arrows field \"u\" has no step 7 inside the volume; its steps: 0"),
            std::string::npos);
  EXPECT_NE(test::messageOf([&] {
              volumeArrowMesh(spec, VolumeMesh{}, {}, "plate.msh");
            }).find("and 'plate.msh' has none (tetrahedra, hexahedra, prisms, pyramids)"),
            std::string::npos);
}

TEST(VolumeArrowsBadInput, CommandLine) {
  const std::string cube = test::quoted(test::dataFile("volume/cube_hex.msh"));
  test::ScratchFolder folder;
  const std::string out = " -o " + test::quoted(folder.file("out.png"));
  for (const auto& [options, message] : std::initializer_list<std::pair<std::string, std::string>>{
           {"--arrows u --arrow-grid 0,4,4", "--arrow-grid: error: '0,4,4' is not NX,NY,NZ"},
           {"--arrows u --arrow-grid 4,4", "'4,4' is not NX,NY,NZ"},
           {"--arrows u --arrow-grid 4,4,4,4", "'4,4,4,4' is not NX,NY,NZ"},
           {"--arrows u --arrow-grid 1000,1000,1000",
            "'1000,1000,1000' asks for 1000 x 1000 x 1000 = 1000000000"},
           {"--arrow-grid 4,4,4", "give the field with --arrows FIELD"},
           {"--arrows f --arrow-grid 4,4,4", "must be a vector of 3 components"},
       }) {
    const test::CommandResult run = test::runCli("render " + cube + " " + options + out);
    EXPECT_EQ(run.exitCode, 2) << options << "\n" << run.output;
    EXPECT_TRUE(test::contains(run.output, message)) << options << "\n" << run.output;
    EXPECT_TRUE(folder.entries().empty()) << options;
  }
  const test::CommandResult good =
      test::runCli("render " + cube + " --arrows u --arrow-grid 3,3,3 --width 32 --height 32 -q" + out);
  EXPECT_EQ(good.exitCode, 0) << good.output;
}

}  // namespace
}  // namespace lancer
