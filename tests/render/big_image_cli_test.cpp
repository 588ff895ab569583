// `lancer render` of images larger than memory: a PNG, BMP or PPM still is streamed to its file in
// bands, so the memory budget counts a few bands, not the image; Ctrl-C part-way leaves the old file.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::contains;
using test::quoted;
using test::runCli;

// 16000 x 12000 as one float image with its 8-bit copy is 3.6 GiB; its bands take a few MiB.
// (--pixel traces one pixel after the checks, so the test does not render the whole picture.)
TEST(BigImageCli, BudgetCountsBandsForAStreamedStillAndTheWholeImageForAGif) {
  test::ScratchFolder folder;
  const std::string size = " --max-memory 64M --width 16000 --height 12000 --pixel 0,0 -o ";
  const test::CommandResult png =
      runCli("render -q " + quoted(test::kTurntableScene) + size + quoted(folder.file("big.png")));
  EXPECT_EQ(png.exitCode, 0) << png.output;
  EXPECT_TRUE(contains(png.output, "pixel 0,0: rgb")) << png.output;

  const test::CommandResult gif =
      runCli("render -q " + quoted(test::kTurntableScene) + size + quoted(folder.file("big.gif")));
  EXPECT_EQ(gif.exitCode, 2) << gif.output;
  EXPECT_TRUE(contains(gif.output,
                       "error: a 16000x12000 image needs 3.6 GiB, more than the memory budget of "
                       "64.0 MiB"))
      << gif.output;
  EXPECT_TRUE(folder.entries().empty());
}

// Ctrl-C (SIGINT from `timeout`) while the bands are being written: exit 130, the old file as it was,
// no temporary file left.
TEST(BigImageCli, InterruptWhileStreamingLeavesTheOldFile) {
  const std::vector<std::uint8_t> old = {'o', 'l', 'd'};
  for (const std::string name : {"big.png", "big.bmp"}) {
    SCOPED_TRACE(name);
    test::ScratchFolder folder;
    test::writeBytes(folder.file(name), old);
    const test::CommandResult result =
        runCli("render -q " + quoted(test::kTurntableScene) + " --width 16000 --height 12000 -o " +
                   quoted(folder.file(name)),
               "timeout -s INT --preserve-status 1.5");
    EXPECT_EQ(result.exitCode, 130) << result.output;
    EXPECT_TRUE(contains(result.output, "lancer: interrupted; ")) << result.output;
    test::expectOnlyFile(folder, name, old);
  }
}

}  // namespace
}  // namespace lancer
