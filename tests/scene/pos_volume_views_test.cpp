// Inside the volume of a list-based .pos view, as a user asks for it (the CLI and scene files), on
// the views gmsh wrote on a tetrahedral cube (tests/data/pos/volume: f = x + 2y + 3z at the nodes,
// u = (1, 2, 3)): a slice seen straight on, unlit, shows at every pixel the map's colour at f of the
// point the pixel sees, whether the view is drawn alone or put on the mesh it was computed on;
// every volume view renders; probes print the closed form; what cannot be met exits 2.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>
#include <string>

#include "support/cli.hpp"
#include "support/files.hpp"
#include "support/slice_colours.hpp"

namespace lancer {
namespace {

constexpr int kSide = 64;

std::string cubePos() { return test::dataFile("pos/volume/cube.pos"); }
std::string cubeMsh() { return test::dataFile("pos/volume/cube.msh"); }

// Straight down at the slice z = 0.3 of the unit cube, the skin hidden (support/slice_colours.hpp);
// `files` is the [[mesh]]'s file (and views) keys.
std::string topViewScene(const std::string& files) {
  return test::topViewSliceScene(
      kSide, files, "skin = \"hidden\"\n\n[[mesh.slice]]\npoint = [0, 0, 0.3]\nnormal = [0, 0, 1]\n");
}

TEST(PosVolumeViews, ASliceOfAViewShowsTheFieldAtEveryPixel) {
  const test::ScratchFolder folder;
  EXPECT_GT(test::expectSliceColours(folder, topViewScene(fmt::format("file = \"{}\"", cubePos()))),
            kSide * kSide / 2);
}

TEST(PosVolumeViews, ASliceOfAViewOnItsMeshShowsTheFieldAtEveryPixel) {
  const test::ScratchFolder folder;
  EXPECT_GT(test::expectSliceColours(
                folder, topViewScene(fmt::format("file = \"{}\"\nviews = [\"{}\"]", cubeMsh(), cubePos()))),
            kSide * kSide / 2);
}

TEST(PosVolumeViews, TheCliDrawsEveryVolumeViewOfAPosFile) {
  const test::ScratchFolder folder;
  const std::string out = folder.file("out.png");
  for (const std::string& input :
       {test::quoted(cubePos()), test::quoted(cubeMsh()) + " " + test::quoted(cubePos())})
    for (const std::string options :
         {"--color-by f --slice z=0.3 --slice x --legend right",  // docs/volume.md's
          "--color-by f --clip y=0.5 --isosurfaces f:3 --streamlines u:5 --arrows u --arrow-grid "
          "3,3,3"}) {
      const test::CommandResult run = test::runCli(
          "render " + input + " " + options + " --width 48 --height 36 -q -o " + test::quoted(out) + " 2>&1");
      EXPECT_EQ(run.exitCode, 0) << input << " " << options << "\n" << run.output;
      EXPECT_TRUE(std::filesystem::exists(out)) << options;
      std::filesystem::remove(out);
    }
}

TEST(PosVolumeViews, ProbesGiveTheClosedForm) {
  const test::CommandResult run =
      test::runCli("probe " + test::quoted(cubePos()) + " --at 0.1,0.2,0.3 --field f 2>&1");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_TRUE(test::contains(run.output, "f at (0.1, 0.2, 0.3), step 0 (t = 0): 1.3999")) << run.output;
  EXPECT_TRUE(test::contains(run.output, "f at (0.1, 0.2, 0.3), step 1 (t = 1): 11.3999")) << run.output;
  const test::CommandResult onMesh =
      test::runCli("probe " + test::quoted(cubeMsh()) + " " + test::quoted(cubePos()) +
                   " --at 0.5,0.5,0.5 --field u 2>&1");
  EXPECT_EQ(onMesh.exitCode, 0) << onMesh.output;
  EXPECT_TRUE(test::contains(onMesh.output, "u at (0.5, 0.5, 0.5), step 0 (t = 0): (1, 2, 3)"))
      << onMesh.output;
}

// GetDP's two dielectric layers (tests/data/pos/layers: v = 1.5 z below z = 0.5, 0.75 + 0.5 (z - 0.5)
// above): its views put on the mesh it solved give the exact potential and the field's jump.
TEST(PosVolumeViews, GetDPsLayersProbeToTheirClosedForm) {
  const std::string folder = test::dataFile("pos/layers/");
  const test::CommandResult run =
      test::runCli("probe " + test::quoted(folder + "layers.msh") + " " + test::quoted(folder + "v.pos") +
                   " " + test::quoted(folder + "e.pos") + " --at 0.5,0.5,0.25 --at 0.5,0.5,0.75 2>&1");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  test::expectContainsAll(run.output, {"v at (0.5, 0.5, 0.25), step 0 (t = 0): 0.375\n",
                                       "v at (0.5, 0.5, 0.75), step 0 (t = 0): 0.875\n",
                                       "-1.5), magnitude 1.5\n", "-0.5), magnitude 0.5\n"});
}

TEST(PosVolumeViews, WhatAViewCannotGiveExitsTwo) {
  const test::ScratchFolder folder;
  const std::string out = folder.file("out.png");
  const std::string surfaces = test::dataFile("pos/heat/t.pos");  // triangles and quadrangles only
  const test::CommandResult slice = test::runCli(
      "render " + test::quoted(surfaces) + " --color-by T --slice z -q -o " + test::quoted(out) + " 2>&1");
  EXPECT_EQ(slice.exitCode, 2) << slice.output;
  EXPECT_TRUE(test::contains(slice.output, "has no volume elements")) << slice.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  const test::CommandResult outside =
      test::runCli("probe " + test::quoted(cubePos()) + " --at 1.5,0.5,0.5 --field f 2>&1");
  EXPECT_EQ(outside.exitCode, 2) << outside.output;
  EXPECT_TRUE(
      test::contains(outside.output, "is inside no volume element (the volume spans (0, 0, 0) to (1, 1, 1))"))
      << outside.output;
  const test::CommandResult flat = test::runCli("probe " + test::quoted(surfaces) + " --at 0,0,0 2>&1");
  EXPECT_EQ(flat.exitCode, 2) << flat.output;
  EXPECT_TRUE(test::contains(flat.output, "has no volume elements")) << flat.output;
}

}  // namespace
}  // namespace lancer
