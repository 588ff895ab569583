#include "lancer/util/thread_count.hpp"

#include <sched.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <thread>

namespace lancer {
namespace {

// The value of environment variable `name` when it is a positive decimal integer (nothing else around it).
std::optional<int> positiveIntegerFromEnv(const char* name) {
  const char* text = std::getenv(name);
  if (text == nullptr) return std::nullopt;
  const char* end = text + std::strlen(text);
  int value = 0;
  const auto [stop, error] = std::from_chars(text, end, value);
  if (error != std::errc{} || stop != end || stop == text || value <= 0) return std::nullopt;
  return value;
}

}  // namespace

int affinityCpuCount() {
#ifdef __linux__
  // A set of CPU_SETSIZE (1024) CPUs first; sched_getaffinity refuses with EINVAL a set smaller than
  // the kernel's, so larger machines get a larger one.
  for (int cpus = CPU_SETSIZE; cpus <= (1 << 20); cpus *= 2) {
    cpu_set_t* set = CPU_ALLOC(cpus);
    if (set == nullptr) break;
    const std::size_t size = CPU_ALLOC_SIZE(cpus);
    const bool read = sched_getaffinity(0, size, set) == 0;
    const bool tooSmall = !read && errno == EINVAL;
    const int count = read ? CPU_COUNT_S(size, set) : 0;
    CPU_FREE(set);
    if (count > 0) return count;
    if (!tooSmall) break;
  }
#endif
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware > 0 ? static_cast<int>(hardware) : 1;
}

DefaultThreadCount defaultThreadCount() {
  const int cpus = affinityCpuCount();
  if (const auto omp = positiveIntegerFromEnv("OMP_NUM_THREADS"))
    return {std::min(*omp, cpus), ThreadCountSource::kOmpNumThreads};
  if (const auto slurm = positiveIntegerFromEnv("SLURM_CPUS_PER_TASK"))
    return {std::min(*slurm, cpus), ThreadCountSource::kSlurmCpusPerTask};
  return {cpus, ThreadCountSource::kAffinity};
}

int resolveThreadCount(int requested) { return requested > 0 ? requested : defaultThreadCount().count; }

}  // namespace lancer
