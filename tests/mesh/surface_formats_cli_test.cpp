// STL, OBJ and PLY through the built CLI, as a user gives them: rendered on their own, described by
// info, coloured by a PLY vertex property, given materials by group from a scene file; a broken one
// refused with exit code 2 and nothing written.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/cli.hpp"
#include "support/files.hpp"
#include "support/test_images.hpp"

namespace lancer {
namespace {

using test::quoted;
using test::runCli;

std::string surfaceFile(const std::string& name) { return quoted(test::dataFile("surface/" + name)); }

TEST(SurfaceFormatsCli, EachFormatRenders) {
  test::ScratchFolder folder;
  for (const char* file : {"box_groups.stl", "box_binary.stl", "box.obj", "groups.obj",
                           "plate_temperature.ply", "polygons.ply"}) {
    const std::string out = folder.file(std::string(file) + ".png");
    const test::CommandResult result =
        runCli("render -q " + surfaceFile(file) + " --width 48 --height 36 -o " + quoted(out));
    EXPECT_EQ(result.exitCode, 0) << file << ": " << result.output;
    EXPECT_EQ(test::pngRgb8(out).size(), 48u * 36u * 3u) << file;
  }
}

TEST(SurfaceFormatsCli, InfoNamesTheFormatGroupsAndFields) {
  test::CommandResult result = runCli("info " + surfaceFile("plate_temperature_bin.ply"));
  EXPECT_EQ(result.exitCode, 0) << result.output;
  test::expectContainsAll(result.output, {"format:          PLY binary_little_endian", "\"temperature\""});
  result = runCli("info " + surfaceFile("box_binary.stl"));
  test::expectContainsAll(result.output, {"format:          STL binary", "\"bottom\"", "\"walls\""});
}

// Share of the picture's pixels whose red channel exceeds the others by 60 (a red material or the
// warm end of a colour map), and the same for blue.
std::pair<double, double> redAndBlueShares(const std::string& png) {
  const std::vector<std::uint8_t> rgb = test::pngRgb8(png);
  std::size_t red = 0, blue = 0;
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
    red += rgb[i] > rgb[i + 1] + 60 && rgb[i] > rgb[i + 2] + 60;
    blue += rgb[i + 2] > rgb[i] + 60 && rgb[i + 2] > rgb[i + 1] + 60;
  }
  const double pixels = static_cast<double>(rgb.size() / 3);
  return {static_cast<double>(red) / pixels, static_cast<double>(blue) / pixels};
}

TEST(SurfaceFormatsCli, APlyPropertyColoursTheMesh) {
  test::ScratchFolder folder;
  const std::string out = folder.file("t.png");
  const test::CommandResult result =
      runCli("render -q " + surfaceFile("plate_temperature.ply") +
             " --color-by temperature --color-map RdBu_r --width 64 --height 48 -o " + quoted(out));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const auto [red, blue] = redAndBlueShares(out);
  EXPECT_GT(red, 0.02);   // the hot corner
  EXPECT_GT(blue, 0.02);  // the cold one
}

TEST(SurfaceFormatsCli, MaterialsByStlSolid) {
  test::ScratchFolder folder;
  folder.copy(test::dataFile("surface/box_groups.stl"), "box.stl");
  folder.write(
      "scene.toml",
      "[render]\nwidth = 64\nheight = 48\n[camera]\nposition = [2.2, -1.6, -1.4]\nlook_at = [0.5, 0.5, 0.5]\n"
      "[[light]]\nposition = [3, -3, -3]\n"
      "[material.red]\nkd = [0.9, 0.05, 0.05]\n[material.blue]\nkd = [0.05, 0.05, 0.9]\n"
      "[[mesh]]\nfile = \"box.stl\"\ngroups = { bottom = \"red\", walls = \"blue\" }\n");
  const test::CommandResult result =
      test::runShell("cd " + quoted(folder.path().string()) + " && '" + LANCER_CLI_PATH +
                     "' render -q scene.toml -o out.png 2>&1");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const auto [red, blue] = redAndBlueShares(folder.file("out.png"));
  EXPECT_GT(red, 0.02);
  EXPECT_GT(blue, 0.02);
}

TEST(SurfaceFormatsCli, ABrokenSurfaceIsRefusedAndNothingIsWritten) {
  test::ScratchFolder folder;
  folder.write("part.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  const std::vector<std::string> before = folder.entriesBelow();
  const test::CommandResult result =
      runCli("render -q " + quoted(folder.file("part.obj")) + " -o " + quoted(folder.file("out.png")));
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(
      result.output.find("part.obj:4:7: error: vertex index 4 is out of range: the file defines 3 vertices"),
      std::string::npos)
      << result.output;
  EXPECT_EQ(folder.entriesBelow(), before);
}

}  // namespace
}  // namespace lancer
