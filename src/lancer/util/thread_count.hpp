// How many threads a stage runs on: the --threads a user asked for, or by default the CPUs this process
// may run on, the same rule for every stage (mesh assembly, accelerator build, the renderer).
#pragma once

namespace lancer {

// Where the default count came from (docs/rendering.md, "Threads").
enum class ThreadCountSource { kAffinity, kOmpNumThreads, kSlurmCpusPerTask };

struct DefaultThreadCount {
  int count = 1;
  ThreadCountSource source = ThreadCountSource::kAffinity;
};

// The CPUs in the calling thread's affinity mask (sched_getaffinity: taskset, a SLURM or cgroup
// cpuset, mpirun's binding), or std::thread::hardware_concurrency() where the mask cannot be read;
// at least 1.
int affinityCpuCount();

// OMP_NUM_THREADS when it is a positive integer, else SLURM_CPUS_PER_TASK when it is one, else
// affinityCpuCount(); never more than affinityCpuCount(), since more threads than CPUs only take turns.
// Read on every call: the environment and the mask may change between renders.
DefaultThreadCount defaultThreadCount();

// `requested` > 0 as it is; 0 (or less): defaultThreadCount().count.
int resolveThreadCount(int requested);

}  // namespace lancer
