// Which processes share a command's work: this one alone, or the ranks of the MPI job it was started
// in (`mpirun -n N lancer ...`). Job-array tasks (--shard) each work alone on their own share.
#pragma once

#include <memory>

#include "lancer/cluster/work_distribution.hpp"

namespace lancer::cli {

// MPI when launched by mpirun/srun as more than one process (and not sharded), else local. Throws
// InputError when started as several processes by a lancer built without MPI, since every process
// would then render and write the whole output.
std::unique_ptr<WorkDistribution> commandDistribution(bool sharded);

// The render threads per rank: --threads when given (> 0), else the distribution's share of the node.
int commandThreads(int requested, const WorkDistribution& distribution);

}  // namespace lancer::cli
