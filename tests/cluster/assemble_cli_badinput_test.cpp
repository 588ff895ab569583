// What `lancer assemble`, `animate --shard` and `render --shard` say about options that cannot work
// together or inputs that are not frames: one line naming what is wrong and what to do, exit code 2,
// and nothing written.
#include <gtest/gtest.h>

#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::quoted;
using test::runCli;
using test::ScratchFolder;

void expectRefused(const std::string& arguments, const std::string& message, const ScratchFolder& folder) {
  const test::CommandResult r = runCli(arguments);
  EXPECT_EQ(r.exitCode, 2) << arguments << "\n" << r.output;
  EXPECT_TRUE(test::contains(r.output, message)) << arguments << "\n" << r.output;
  EXPECT_TRUE(folder.entries().empty()) << arguments;
}

TEST(AssembleCliBadInput, EachMisuseIsNamed) {
  ScratchFolder folder;
  const std::string scene = quoted(test::kTurntableScene);
  const std::string frames = quoted(folder.file("f_%04d.png"));
  expectRefused("assemble " + quoted(folder.file("f.png")) + " -o " + quoted(folder.file("a.gif")),
                "the frames need a pattern with %d or %04d, e.g. 'frames/%04d.png'", folder);
  expectRefused("assemble " + quoted(folder.file("f_%04d.ppm")) + " -o " + quoted(folder.file("a.gif")),
                "assemble reads PNG frames (render them as frame_%04d.png)", folder);
  expectRefused("assemble " + frames + " -o " + quoted(folder.file("b_%04d.png")),
                "assemble writes an animated .gif or .png, not frames", folder);
  expectRefused("assemble " + frames + " -o " + quoted(folder.file("a.gif")),
                "error: no frames: there is no " + folder.file("f_0000.png"), folder);
  expectRefused(
      "assemble --tiles --fps 10 " + quoted(folder.file("p.part-0-of-1")) + " -o " +
          quoted(folder.file("p.png")),
      "--tiles: error: --tiles stitches a still: --frames, --fps, --loop, --dither and --palette do "
      "not apply",
      folder);
  expectRefused("animate " + scene + " -o " + frames + " --frame-range 3-9",
                "--frame-range: error: frame 9 is past the end: the animation has 4 frames, 0 to 3", folder);
  expectRefused("animate " + scene + " -o " + quoted(folder.file("a.png")) + " --skip-existing",
                "--skip-existing: error: --shard, --frame-range and --skip-existing write numbered frames",
                folder);
  expectRefused("render " + scene + " -o " + quoted(folder.file("r.png")) + " --shard 4/4",
                "--shard: error: '4/4' is not a shard: use I/N with 0 <= I < N (e.g. 3/16), or auto", folder);
}

}  // namespace
}  // namespace lancer
