// Job arrays through the built CLI on the committed 4-frame turntable: numbered frames rendered as
// shards (explicit, and --shard auto from faked SLURM variables) and assembled give the bytes of
// `lancer animate -o` directly (GIF and APNG); --skip-existing resumes; a missing or foreign frame is
// named; `render --shard` parts stitched by `assemble --tiles` are the single render's file, path
// traced too and legends in the picture included.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::expectSameFile;
using test::quoted;
using test::runCli;
using test::ScratchFolder;

const std::string kScene = quoted(test::kTurntableScene);

// Renders `input` with `options` as three `--shard` tasks writing parts of `output`, then stitches
// them with `assemble --tiles`; returns the failing command's output, or "" when all succeeded.
std::string renderAsThreeTasks(const ScratchFolder& folder, const std::string& input,
                               const std::string& options, const std::string& output) {
  for (const char* shard : {"0/3", "1/3", "2/3"}) {
    const test::CommandResult r =
        runCli("render -q " + input + options + " -o " + quoted(folder.file(output)) + " --shard " + shard);
    if (r.exitCode != 0) return r.output;
  }
  const test::CommandResult r = runCli("assemble -q --tiles " + quoted(folder.path().string()) + "/" +
                                       output + ".part-* -o " + quoted(folder.file(output)));
  return r.exitCode == 0 ? "" : r.output;
}

TEST(AssembleCli, ShardsAssembledAreTheDirectGifAndApng) {
  ScratchFolder folder;
  ASSERT_EQ(runCli("animate -q " + kScene + " -o " + quoted(folder.file("direct.gif"))).exitCode, 0);
  ASSERT_EQ(runCli("animate -q " + kScene + " --loop 2 -o " + quoted(folder.file("direct.png"))).exitCode, 0);
  const std::string frames = quoted(folder.file("f/%04d.png"));
  std::filesystem::create_directory(folder.file("f"));
  for (const char* shard : {"0/3", "1/3", "2/3"}) {
    const test::CommandResult r = runCli("animate " + kScene + " -o " + frames + " --shard " + shard);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    if (std::string(shard) == "1/3") {
      EXPECT_TRUE(test::contains(r.output, "task 1 of 3 (--shard 1/3) renders frames 1 (1 frame)"))
          << r.output;
    }
  }
  const test::CommandResult gif = runCli("assemble " + frames + " -o " + quoted(folder.file("a.gif")));
  ASSERT_EQ(gif.exitCode, 0) << gif.output;
  EXPECT_TRUE(test::contains(gif.output, "4 frames 64x48 assembled")) << gif.output;
  expectSameFile(folder.file("a.gif"), folder.file("direct.gif"));
  ASSERT_EQ(runCli("assemble -q --loop 2 " + frames + " -o " + quoted(folder.file("a.png"))).exitCode, 0);
  expectSameFile(folder.file("a.png"), folder.file("direct.png"));
}

TEST(AssembleCli, ShardAutoTakesTheSlurmArrayTaskAndRefusesADisagreeingSpec) {
  ScratchFolder folder;
  const std::string frames = quoted(folder.file("f_%04d.png"));
  // sbatch --array=1-3:2 (ids 1 and 3) as task id 3: the second of two tasks, frames 1 and 3.
  const std::string slurm =
      "env SLURM_ARRAY_TASK_ID=3 SLURM_ARRAY_TASK_COUNT=2 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_STEP=2";
  const test::CommandResult r = runCli("animate " + kScene + " -o " + frames + " --shard auto", slurm);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(test::contains(r.output,
                             "task 1 of 2 (SLURM_ARRAY_TASK_ID=3 (of SLURM_ARRAY_TASK_COUNT=2, min 1, "
                             "step 2)) renders frames 1, 3 (2 frames)"))
      << r.output;
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"f_0001.png", "f_0003.png"}));
  const test::CommandResult wrong = runCli("animate " + kScene + " -o " + frames + " --shard 0/2", slurm);
  EXPECT_EQ(wrong.exitCode, 2);
  EXPECT_TRUE(test::contains(wrong.output, "--shard 0/2 disagrees with the scheduler")) << wrong.output;
  // The missing frames are named, then --skip-existing renders only them.
  const test::CommandResult missing = runCli("assemble " + frames + " -o " + quoted(folder.file("a.gif")));
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_TRUE(test::contains(missing.output, folder.file("f_0000.png") + ": error: frame 0 of 4 is missing"))
      << missing.output;
  const test::CommandResult resumed = runCli("animate " + kScene + " -o " + frames + " --skip-existing");
  ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
  EXPECT_TRUE(test::contains(resumed.output, "--skip-existing: 2 of 4 frames are already there"))
      << resumed.output;
  EXPECT_TRUE(test::contains(resumed.output, "2 frames 64x48")) << resumed.output;
  EXPECT_EQ(runCli("assemble -q " + frames + " -o " + quoted(folder.file("a.gif"))).exitCode, 0);
}

TEST(AssembleCli, AForeignFrameIsNamedAndNothingIsWritten) {
  ScratchFolder folder;
  const std::string frames = quoted(folder.file("f_%04d.png"));
  ASSERT_EQ(runCli("animate -q " + kScene + " -o " + frames).exitCode, 0);
  ASSERT_EQ(runCli("render -q " + kScene + " --width 32 -o " + quoted(folder.file("f_0002.png"))).exitCode,
            0);
  folder.write("a.gif", "old");
  const test::CommandResult r = runCli("assemble " + frames + " -o " + quoted(folder.file("a.gif")));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(test::contains(
      r.output, folder.file("f_0002.png") +
                    ": error: frame 2 is 32x48 sRGB, but frame 0 is 64x48 sRGB: not from the same "
                    "animation"))
      << r.output;
  EXPECT_EQ(folder.read("a.gif"), "old");
  // --skip-existing renders the foreign frame again (it is not a complete frame of this animation).
  const test::CommandResult resumed = runCli("animate " + kScene + " -o " + frames + " --skip-existing");
  EXPECT_TRUE(test::contains(resumed.output, "3 of 4 frames are already there")) << resumed.output;
  const test::CommandResult animated =
      runCli("animate " + kScene + " -o " + quoted(folder.file("x.gif")) + " --shard 0/2");
  EXPECT_EQ(animated.exitCode, 2);
  EXPECT_TRUE(test::contains(animated.output,
                             "--shard: error: --shard, --frame-range and --skip-existing write "
                             "numbered frames"))
      << animated.output;
}

TEST(AssembleCli, RenderShardPartsStitchedAreTheSingleRender) {
  ScratchFolder folder;
  const std::string size = " --width 70 --height 230 --srgb";
  ASSERT_EQ(runCli("render -q " + kScene + size + " -o " + quoted(folder.file("direct.png"))).exitCode, 0);
  for (const char* shard : {"0/3", "1/3", "2/3"}) {
    const test::CommandResult r =
        runCli("render " + kScene + size + " -o " + quoted(folder.file("t.png")) + " --shard " + shard);
    ASSERT_EQ(r.exitCode, 0) << r.output;
  }
  EXPECT_FALSE(std::filesystem::exists(folder.file("t.png")));
  const test::CommandResult missing =
      runCli("assemble --tiles " + quoted(folder.file("t.png.part-0-of-3")) + " " +
             quoted(folder.file("t.png.part-2-of-3")) + " -o " + quoted(folder.file("t.png")));
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_TRUE(test::contains(missing.output, "part 1 of 3 is missing")) << missing.output;
  const test::CommandResult r = runCli("assemble --tiles " + quoted(folder.path().string()) +
                                       "/t.png.part-* -o " + quoted(folder.file("t.png")));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  expectSameFile(folder.file("t.png"), folder.file("direct.png"));
}

TEST(AssembleCli, PathTracedShardsAndThreadCountsGiveTheSameBytes) {
  // The path tracer's samples come from per-pixel streams: one thread, two, or three job-array
  // parts stitched write one file.
  ScratchFolder folder;
  const std::string look = " --look studio --samples 4 --noise 0.05 --tonemap filmic --width 40 --height 150";
  ASSERT_EQ(
      runCli("render -q " + kScene + look + " --threads 1 -o " + quoted(folder.file("one.png"))).exitCode, 0);
  ASSERT_EQ(
      runCli("render -q " + kScene + look + " --threads 2 -o " + quoted(folder.file("two.png"))).exitCode, 0);
  expectSameFile(folder.file("two.png"), folder.file("one.png"));
  ASSERT_EQ(renderAsThreeTasks(folder, kScene, look, "t.png"), "");
  expectSameFile(folder.file("t.png"), folder.file("one.png"));
}

TEST(AssembleCli, LegendsDrawnByTheShardsAreTheSingleRendersLegends) {
  // Each task draws the part of the legends that falls in its band items: a vertical legend (right)
  // and gmsh's horizontal scale (--gmsh-view, ShowScale: bottom) straddle several tasks' rows.
  ScratchFolder folder;
  const std::string mesh = test::dataFile("results/cantilever.msh");
  folder.write("legend.toml", "[[mesh]]\nfile = \"" + mesh +
                                  "\"\ncolor_by = { field = \"stress\", component = \"von_mises\", title = "
                                  "\"von Mises stress\", units = \"MPa\", legend = \"right\" }\n");
  const std::string options = test::dataFile("results/cantilever.msh.opt");
  for (const std::string& input :
       {quoted(folder.file("legend.toml")), quoted(mesh) + " --gmsh-view " + quoted(options)}) {
    const std::string size = " --width 120 --height 230";
    ASSERT_EQ(runCli("render -q " + input + size + " -o " + quoted(folder.file("direct.png"))).exitCode, 0);
    ASSERT_EQ(renderAsThreeTasks(folder, input, size, "t.png"), "");
    expectSameFile(folder.file("t.png"), folder.file("direct.png"));
    std::filesystem::remove(folder.file("t.png"));
    for (const auto& entry : std::filesystem::directory_iterator(folder.path()))
      if (entry.path().filename().string().rfind("t.png.part-", 0) == 0)
        std::filesystem::remove(entry.path());
  }
}

}  // namespace
}  // namespace lancer
