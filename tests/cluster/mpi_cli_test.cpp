// `mpirun -n N lancer ...` on loopback (--oversubscribe: the CI machine has two cores): animations
// (GIF, APNG, numbered frames) and a streamed still are byte-identical to a single process for 2 and
// 3 ranks; a rank killed mid-run or failing on bad input ends the job non-zero, named, with an existing
// output untouched. A lancer built without MPI says so instead of rendering N times.
#include <gtest/gtest.h>

#include <cstdlib>
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

bool mpirunInstalled() { return std::system("command -v mpirun >/dev/null 2>&1") == 0; }

// CI runs as root, which mpirun refuses unless told otherwise.
std::string mpirun(int ranks) {
  return "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -n " + std::to_string(ranks) +
         " --oversubscribe";
}

#if LANCER_TEST_MPI

TEST(MpiCli, AnimationsAreByteIdenticalToOneProcess) {
  if (!mpirunInstalled()) GTEST_SKIP() << "mpirun is not installed";
  ScratchFolder folder;
  const std::string options = " --frames 7 --width 40 --height 30";
  ASSERT_EQ(runCli("animate -q " + kScene + options + " -o " + quoted(folder.file("one.gif"))).exitCode, 0);
  ASSERT_EQ(runCli("animate -q " + kScene + options + " -o " + quoted(folder.file("one.png"))).exitCode, 0);
  ASSERT_EQ(runCli("animate -q " + kScene + options + " -o " + quoted(folder.file("one_%d.ppm"))).exitCode,
            0);
  for (const int ranks : {2, 3}) {
    SCOPED_TRACE(ranks);
    const test::CommandResult gif = runCli(
        "animate " + kScene + options + " --threads 1 -o " + quoted(folder.file("n.gif")), mpirun(ranks));
    ASSERT_EQ(gif.exitCode, 0) << gif.output;
    EXPECT_TRUE(test::contains(gif.output, "7 frames 40x30")) << gif.output;
    EXPECT_TRUE(test::contains(gif.output, "on " + std::to_string(ranks) + " ranks")) << gif.output;
    expectSameFile(folder.file("n.gif"), folder.file("one.gif"));
    ASSERT_EQ(runCli("animate -q " + kScene + options + " -o " + quoted(folder.file("n.png")), mpirun(ranks))
                  .exitCode,
              0);
    expectSameFile(folder.file("n.png"), folder.file("one.png"));
    ASSERT_EQ(
        runCli("animate -q " + kScene + options + " -o " + quoted(folder.file("n_%d.ppm")), mpirun(ranks))
            .exitCode,
        0);
    for (int k = 0; k < 7; ++k)
      expectSameFile(folder.file("n_" + std::to_string(k) + ".ppm"),
                     folder.file("one_" + std::to_string(k) + ".ppm"));
  }
}

TEST(MpiCli, AStreamedStillIsByteIdenticalToOneProcess) {
  if (!mpirunInstalled()) GTEST_SKIP() << "mpirun is not installed";
  ScratchFolder folder;
  const std::string options = " --width 50 --height 300 --samples 4";  // 10 bands
  for (const char* name : {"s.png", "s.bmp"}) {
    SCOPED_TRACE(name);
    ASSERT_EQ(
        runCli("render -q " + kScene + options + " -o " + quoted(folder.file(std::string("one-") + name)))
            .exitCode,
        0);
    for (const int ranks : {2, 3}) {
      const test::CommandResult r =
          runCli("render -q " + kScene + options + " -o " + quoted(folder.file(name)), mpirun(ranks));
      ASSERT_EQ(r.exitCode, 0) << r.output;
      expectSameFile(folder.file(name), folder.file(std::string("one-") + name));
    }
  }
}

TEST(MpiCli, AKilledRankEndsTheJobAndLeavesTheOutputAsItWas) {
  if (!mpirunInstalled()) GTEST_SKIP() << "mpirun is not installed";
  ScratchFolder folder;
  folder.write("keep.gif", "the old animation");
  // Rank 1 is killed (SIGKILL, as the out-of-memory killer does) a moment into a long animation.
  const std::string command =
      mpirun(2) + " sh -c 'if [ \"$OMPI_COMM_WORLD_RANK\" = 1 ]; then (sleep 1; kill -9 $$) & fi; exec " +
      std::string(LANCER_CLI_PATH) + " animate -q " + test::kTurntableScene +
      " --frames 300 --width 160 --height 120 --samples 16 -o " + folder.file("keep.gif") + "' 2>&1";
  const test::CommandResult r = test::runShell(command);
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_TRUE(test::contains(r.output, "rank 1")) << r.output;
  EXPECT_TRUE(test::contains(r.output, "signal 9")) << r.output;
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"keep.gif"}));
  EXPECT_EQ(folder.read("keep.gif"), "the old animation");
}

TEST(MpiCli, CtrlCOnMpirunLeavesTheOutputAsItWas) {
  if (!mpirunInstalled()) GTEST_SKIP() << "mpirun is not installed";
  ScratchFolder folder;
  folder.write("keep.png", "the old poster");
  // Ctrl-C as a terminal sends it: SIGINT to mpirun's process group (the ranks are in it), a moment
  // into a streamed still that takes many seconds.
  const std::string command = "bash -c 'set -m; " + mpirun(2) + " " + std::string(LANCER_CLI_PATH) +
                              " render -q " + test::kTurntableScene +
                              " --width 2000 --height 2000 --samples 16 -o " + folder.file("keep.png") +
                              " & job=$!; sleep 2; kill -INT -- -$job; wait $job' 2>&1";
  const test::CommandResult r = test::runShell(command);
  // (Whether rank 0's "interrupted" line gets out depends on how soon mpirun kills its ranks.)
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"keep.png"}));
  EXPECT_EQ(folder.read("keep.png"), "the old poster");
}

TEST(MpiCli, BadInputOnOneRankIsNamedWithTheRank) {
  if (!mpirunInstalled()) GTEST_SKIP() << "mpirun is not installed";
  ScratchFolder folder;
  const std::string command =
      mpirun(2) + " sh -c 'in=" + test::kTurntableScene +
      "; if [ \"$OMPI_COMM_WORLD_RANK\" = 1 ]; then in=" + folder.file("absent.toml") + "; fi; exec " +
      std::string(LANCER_CLI_PATH) + " animate -q $in -o " + folder.file("a.gif") + "' 2>&1";
  const test::CommandResult r = test::runShell(command);
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_TRUE(
      test::contains(r.output, "lancer: rank 1 of 2: " + folder.file("absent.toml") + ": error: cannot open"))
      << r.output;
  EXPECT_TRUE(folder.entries().empty());
}

#else

TEST(MpiCli, ABuildWithoutMpiSaysSoUnderMpirun) {
  if (!mpirunInstalled()) GTEST_SKIP() << "mpirun is not installed";
  ScratchFolder folder;
  const test::CommandResult r =
      runCli("animate -q " + kScene + " -o " + quoted(folder.file("a.gif")), mpirun(2));
  EXPECT_NE(r.exitCode, 0);
  EXPECT_TRUE(test::contains(r.output, "this lancer was built without MPI")) << r.output;
  EXPECT_TRUE(folder.entries().empty());
}

#endif

}  // namespace
}  // namespace lancer
