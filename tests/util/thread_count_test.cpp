// The default thread count: the CPUs of the affinity mask, lowered by OMP_NUM_THREADS, then
// SLURM_CPUS_PER_TASK, and never past the mask.
#include "lancer/util/thread_count.hpp"

#include <gtest/gtest.h>
#include <sched.h>

#include <algorithm>
#include <optional>
#include <string>
#include <thread>

#include "support/scoped_env.hpp"

namespace lancer {
namespace {

using test::ScopedEnv;

int maskCpuCount() {
  cpu_set_t mask;
  CPU_ZERO(&mask);
  if (sched_getaffinity(0, sizeof mask, &mask) != 0) return 0;
  return CPU_COUNT(&mask);
}

// Runs `body` on a new thread whose affinity mask is one CPU of this thread's mask (the test
// thread's own mask stays as it was).
template <typename Body>
void onOneCpu(Body&& body) {
  std::thread pinned([&] {
    cpu_set_t mask;
    CPU_ZERO(&mask);
    ASSERT_EQ(sched_getaffinity(0, sizeof mask, &mask), 0);
    int first = 0;
    while (!CPU_ISSET(first, &mask)) ++first;
    CPU_ZERO(&mask);
    CPU_SET(first, &mask);
    ASSERT_EQ(sched_setaffinity(0, sizeof mask, &mask), 0);
    body();
  });
  pinned.join();
}

TEST(ThreadCount, IsTheAffinityMaskWithoutVariables) {
  const ScopedEnv omp("OMP_NUM_THREADS", std::nullopt);
  const ScopedEnv slurm("SLURM_CPUS_PER_TASK", std::nullopt);
  const int cpus = maskCpuCount();
  ASSERT_GT(cpus, 0);
  EXPECT_EQ(affinityCpuCount(), cpus);
  const DefaultThreadCount threads = defaultThreadCount();
  EXPECT_EQ(threads.count, cpus);
  EXPECT_EQ(threads.source, ThreadCountSource::kAffinity);
  EXPECT_EQ(resolveThreadCount(0), cpus);
  EXPECT_EQ(resolveThreadCount(-1), cpus);
  EXPECT_EQ(resolveThreadCount(3), 3);
}

TEST(ThreadCount, FollowsTheMaskOfTheCallingThread) {
  const ScopedEnv omp("OMP_NUM_THREADS", std::nullopt);
  const ScopedEnv slurm("SLURM_CPUS_PER_TASK", std::nullopt);
  onOneCpu([] {
    EXPECT_EQ(affinityCpuCount(), 1);
    EXPECT_EQ(resolveThreadCount(0), 1);
    EXPECT_EQ(resolveThreadCount(5), 5);  // --threads is taken as it is
  });
}

TEST(ThreadCount, OmpNumThreadsWinsOverSlurmCpusPerTask) {
  const ScopedEnv omp("OMP_NUM_THREADS", "1");
  const ScopedEnv slurm("SLURM_CPUS_PER_TASK", "2");
  DefaultThreadCount threads = defaultThreadCount();
  EXPECT_EQ(threads.count, 1);
  EXPECT_EQ(threads.source, ThreadCountSource::kOmpNumThreads);

  const ScopedEnv noOmp("OMP_NUM_THREADS", std::nullopt);
  threads = defaultThreadCount();
  EXPECT_EQ(threads.count, std::min(2, maskCpuCount()));
  EXPECT_EQ(threads.source, ThreadCountSource::kSlurmCpusPerTask);
}

TEST(ThreadCount, NeverExceedsTheAffinityMask) {
  const ScopedEnv slurm("SLURM_CPUS_PER_TASK", std::nullopt);
  const int cpus = maskCpuCount();
  {
    const ScopedEnv omp("OMP_NUM_THREADS", std::to_string(cpus + 7));
    EXPECT_EQ(defaultThreadCount().count, cpus);
  }
  onOneCpu([] {
    const ScopedEnv omp("OMP_NUM_THREADS", "64");
    const ScopedEnv slurmToo("SLURM_CPUS_PER_TASK", "64");
    EXPECT_EQ(defaultThreadCount().count, 1);
    EXPECT_EQ(resolveThreadCount(0), 1);
  });
}

TEST(ThreadCount, IgnoresWhatIsNotAPositiveInteger) {
  const ScopedEnv slurm("SLURM_CPUS_PER_TASK", std::nullopt);
  for (const char* bad : {"", "0", "-2", "+2", " 2", "2 ", "2x", "auto", "4,2", "1.5", "99999999999"}) {
    const ScopedEnv omp("OMP_NUM_THREADS", bad);
    EXPECT_EQ(defaultThreadCount().source, ThreadCountSource::kAffinity) << "OMP_NUM_THREADS='" << bad << "'";
    const ScopedEnv noOmp("OMP_NUM_THREADS", std::nullopt);
    const ScopedEnv slurmBad("SLURM_CPUS_PER_TASK", bad);
    EXPECT_EQ(defaultThreadCount().source, ThreadCountSource::kAffinity)
        << "SLURM_CPUS_PER_TASK='" << bad << "'";
  }
}

}  // namespace
}  // namespace lancer
