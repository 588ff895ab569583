// Job-array sharding: --shard I/N and auto from SLURM's or mpirun's variables (array ids from MIN in
// STEPs), the check that an explicit shard agrees with the scheduler, and which frames a task owns.
#include "lancer/cluster/shard.hpp"

#include <gtest/gtest.h>

#include <map>

#include "support/input_errors.hpp"

namespace lancer {
namespace {

EnvironmentLookup fakeEnvironment(std::map<std::string, std::string> variables) {
  return [variables](const std::string& name) -> std::optional<std::string> {
    const auto it = variables.find(name);
    if (it == variables.end()) return std::nullopt;
    return it->second;
  };
}

TEST(Shard, ExplicitSpecWithoutASchedulerIsTakenAsItIs) {
  const ScheduledShard shard = resolveShard("3/16", fakeEnvironment({}));
  EXPECT_EQ(shard.shard, (Shard{3, 16}));
}

TEST(Shard, MalformedSpecsAreRefusedWithTheForm) {
  for (const char* spec : {"16/16", "3", "a/4", "-1/4", "1/0", "1/4x", ""}) {
    SCOPED_TRACE(spec);
    EXPECT_NE(test::messageOf([&] {
                resolveShard(spec, fakeEnvironment({}));
              }).find("--shard: error: '" + std::string(spec) + "' is not a shard: use I/N with 0 <= I < N"),
              std::string::npos);
  }
}

TEST(Shard, SlurmArrayIdsCountFromMinInSteps) {
  // sbatch --array=1-31:2 gives ids 1, 3, ..., 31: 16 tasks; id 7 is the fourth.
  const auto environment = fakeEnvironment({{"SLURM_ARRAY_TASK_ID", "7"},
                                            {"SLURM_ARRAY_TASK_COUNT", "16"},
                                            {"SLURM_ARRAY_TASK_MIN", "1"},
                                            {"SLURM_ARRAY_TASK_STEP", "2"},
                                            {"SLURM_PROCID", "0"},
                                            {"SLURM_NTASKS", "1"}});
  const ScheduledShard shard = resolveShard("auto", environment);
  EXPECT_EQ(shard.shard, (Shard{3, 16}));
  EXPECT_NE(shard.source.find("SLURM_ARRAY_TASK_ID=7"), std::string::npos) << shard.source;
  // Without COUNT, MAX gives it.
  const auto withMax = fakeEnvironment(
      {{"SLURM_ARRAY_TASK_ID", "12"}, {"SLURM_ARRAY_TASK_MIN", "10"}, {"SLURM_ARRAY_TASK_MAX", "13"}});
  EXPECT_EQ(resolveShard("auto", withMax).shard, (Shard{2, 4}));
}

TEST(Shard, SlurmStepTasksThenOpenMpiRanks) {
  EXPECT_EQ(resolveShard("auto", fakeEnvironment({{"SLURM_PROCID", "2"}, {"SLURM_NTASKS", "5"}})).shard,
            (Shard{2, 5}));
  EXPECT_EQ(
      resolveShard("auto", fakeEnvironment({{"OMPI_COMM_WORLD_RANK", "1"}, {"OMPI_COMM_WORLD_SIZE", "3"}}))
          .shard,
      (Shard{1, 3}));
}

TEST(Shard, AutoWithoutASchedulerSaysWhatItLookedFor) {
  EXPECT_EQ(test::messageOf([] { resolveShard("auto", fakeEnvironment({})); }),
            "--shard: error: --shard auto found no task number: none of SLURM_ARRAY_TASK_ID, SLURM_PROCID or "
            "OMPI_COMM_WORLD_RANK is set; give --shard I/N");
}

TEST(Shard, AnExplicitSpecMustAgreeWithTheScheduler) {
  const auto environment = fakeEnvironment({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "4"}});
  EXPECT_EQ(resolveShard("2/4", environment).shard, (Shard{2, 4}));
  const std::string message = test::messageOf([&] { resolveShard("1/4", environment); });
  EXPECT_NE(
      message.find("--shard 1/4 disagrees with the scheduler, which started this process as task 2 of 4"),
      std::string::npos)
      << message;
  // A single-task job (plain sbatch) names no set to disagree with.
  EXPECT_EQ(resolveShard("1/4", fakeEnvironment({{"SLURM_PROCID", "0"}, {"SLURM_NTASKS", "1"}})).shard,
            (Shard{1, 4}));
}

TEST(Shard, ArrayIdsOffTheStepAreRefused) {
  const auto environment = fakeEnvironment({{"SLURM_ARRAY_TASK_ID", "4"},
                                            {"SLURM_ARRAY_TASK_COUNT", "16"},
                                            {"SLURM_ARRAY_TASK_MIN", "1"},
                                            {"SLURM_ARRAY_TASK_STEP", "2"}});
  EXPECT_NE(test::messageOf([&] {
              resolveShard("auto", environment);
            }).find("task 4 is not one of the 16 tasks from 1 in steps of 2"),
            std::string::npos);
  EXPECT_NE(test::messageOf([] {
              resolveShard("auto",
                           fakeEnvironment({{"SLURM_ARRAY_TASK_ID", "x"}, {"SLURM_ARRAY_TASK_COUNT", "4"}}));
            }).find("SLURM_ARRAY_TASK_ID: error: 'x' is not a task number"),
            std::string::npos);
}

TEST(Shard, FramesOfAShardAreThoseWithKModNEqualToI) {
  EXPECT_EQ(shardFrames(10, std::nullopt, Shard{1, 4}), (std::vector<int>{1, 5, 9}));
  EXPECT_EQ(shardFrames(10, FrameRange{3, 6}, Shard{}), (std::vector<int>{3, 4, 5, 6}));
  EXPECT_EQ(shardFrames(10, FrameRange{3, 9}, Shard{0, 3}), (std::vector<int>{3, 6, 9}));
  // Every frame belongs to exactly one shard.
  std::vector<int> all;
  for (int i = 0; i < 7; ++i)
    for (const int k : shardFrames(360, std::nullopt, Shard{i, 7})) all.push_back(k);
  std::sort(all.begin(), all.end());
  ASSERT_EQ(all.size(), 360u);
  for (int k = 0; k < 360; ++k) EXPECT_EQ(all[static_cast<std::size_t>(k)], k);
  EXPECT_EQ(describeFrames(shardFrames(360, std::nullopt, Shard{0, 4})), "0, 4, 8, 12 ... 356 (90 frames)");
}

TEST(Shard, FrameRangesAreCheckedAgainstTheAnimation) {
  EXPECT_EQ(parseFrameRange("5", 10).first, 5);
  EXPECT_EQ(parseFrameRange("2-9", 10).last, 9);
  EXPECT_EQ(test::messageOf([] { parseFrameRange("2-10", 10); }),
            "--frame-range: error: frame 10 is past the end: the animation has 10 frames, 0 to 9");
  EXPECT_NE(test::messageOf([] { parseFrameRange("5-2", 10); }).find("'5-2' is not a frame range"),
            std::string::npos);
}

}  // namespace
}  // namespace lancer
