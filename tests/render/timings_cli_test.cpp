// `lancer render --timings` and `lancer animate --timings`: one line naming every preparation stage
// in the order it ran (a mesh: read, setup, orient, normals, scene, accel build; a scene file: setup
// first) with its seconds; nothing without it; with --build-alongside too, and the same picture.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::quoted;

const std::regex kTimingsLine(
    R"(timings: (setup [0-9.]+ s, read [0-9.]+ s|read [0-9.]+ s, setup [0-9.]+ s), orient [0-9.]+ s, )"
    R"(normals [0-9.]+ s, scene [0-9.]+ s, accel build [0-9.]+ s)");

TEST(TimingsCli, RenderOfAMeshAndOfASceneNameEveryStage) {
  const test::ScratchFolder folder;
  for (const std::string& input : {test::dataFile("render/bracket_ortho.toml"),
                                   std::string(LANCER_SOURCE_DIR) + "/examples/meshes/bracket.msh"}) {
    const test::CommandResult result =
        test::runCli("render " + quoted(input) + " -q --timings --width 32 --height 24 -o " +
                     quoted(folder.file("a.png")));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(std::regex_search(result.output, kTimingsLine)) << result.output;
  }
}

TEST(TimingsCli, AnimatePrintsThemOnceAndNothingWithoutTheFlag) {
  const test::ScratchFolder folder;
  const std::string scene = quoted(test::dataFile("render/bracket_ortho.toml"));
  const test::CommandResult timed = test::runCli("animate " + scene + " -q --timings --frames 2 --width 32 " +
                                                 "--height 24 -o " + quoted(folder.file("a.gif")));
  ASSERT_EQ(timed.exitCode, 0) << timed.output;
  EXPECT_TRUE(std::regex_search(timed.output, kTimingsLine)) << timed.output;
  const test::CommandResult plain =
      test::runCli("render " + scene + " -q --width 32 --height 24 -o " + quoted(folder.file("b.png")));
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  EXPECT_FALSE(test::contains(plain.output, "timings:")) << plain.output;
}

TEST(TimingsCli, TheBuildAlongsideGivesTheSamePictureAndNamesEveryStage) {
  const test::ScratchFolder folder;
  const std::string mesh = quoted(std::string(LANCER_SOURCE_DIR) + "/examples/meshes/bracket.msh");
  const test::CommandResult alongside =
      test::runCli("render " + mesh + " -q --timings --build-alongside --width 32 --height 24 -o " +
                   quoted(folder.file("alongside.ppm")));
  ASSERT_EQ(alongside.exitCode, 0) << alongside.output;
  EXPECT_TRUE(std::regex_search(alongside.output, kTimingsLine)) << alongside.output;
  const test::CommandResult serial =
      test::runCli("render " + mesh + " -q --width 32 --height 24 -o " + quoted(folder.file("serial.ppm")));
  ASSERT_EQ(serial.exitCode, 0) << serial.output;
  EXPECT_EQ(test::readFileBytes(folder.file("alongside.ppm")),
            test::readFileBytes(folder.file("serial.ppm")));
}

}  // namespace
}  // namespace lancer
