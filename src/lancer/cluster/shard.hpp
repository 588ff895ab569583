// Job-array sharding: which of N independent tasks this process is (`--shard I/N` or `--shard auto`
// from the scheduler's environment), and which frames of an animation it renders.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lancer {

// Task `index` of `count` independent tasks (0 <= index < count).
struct Shard {
  int index = 0;
  int count = 1;
  friend bool operator==(const Shard&, const Shard&) = default;
};

// A shard with where it came from, for messages: "SLURM_ARRAY_TASK_ID=5 (of 8, min 0, step 1)".
struct ScheduledShard {
  Shard shard;
  std::string source;
};

// Looks an environment variable up; nullopt when it is not set. Tests pass their own.
using EnvironmentLookup = std::function<std::optional<std::string>(const std::string& name)>;
// The process's environment (getenv).
EnvironmentLookup processEnvironment();

// The task the scheduler started this process as, from, in order: a SLURM job array
// (SLURM_ARRAY_TASK_ID, _COUNT, _MIN, _STEP; ids need not start at 0), a SLURM step's tasks
// (SLURM_PROCID of SLURM_NTASKS), Open MPI's mpirun (OMPI_COMM_WORLD_RANK of _SIZE). nullopt when none
// is set. Throws InputError for values that do not make a task of a set (non-numbers, id past the end).
std::optional<ScheduledShard> scheduledShard(const EnvironmentLookup& environment);

// `--shard I/N` or `--shard auto`. An explicit I/N must agree with the scheduler's environment when
// that names a set of more than one task (a typo in an array script would otherwise render the same
// frames twice and leave others out); `auto` needs one. Throws InputError located at "--shard".
ScheduledShard resolveShard(const std::string& spec, const EnvironmentLookup& environment);

// Frames first..last, both included.
struct FrameRange {
  int first = 0;
  int last = 0;
};

// "A-B" (or "A" for one frame), checked against the animation's `frameCount` frames. InputError at
// "--frame-range".
FrameRange parseFrameRange(const std::string& text, int frameCount);

// The frames a task renders: those of `range` (all when nullopt) whose number k has
// k % shard.count == shard.index, in increasing order.
std::vector<int> shardFrames(int frameCount, const std::optional<FrameRange>& range, const Shard& shard);

// "0, 4, 8 ... 356 (90 frames)": for the line a task prints about what it owns.
std::string describeFrames(const std::vector<int>& frames);

}  // namespace lancer
