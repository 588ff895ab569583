#include "command_distribution.hpp"

#include <fmt/format.h>

#include "lancer/cluster/mpi_distribution.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer::cli {

std::unique_ptr<WorkDistribution> commandDistribution(bool sharded) {
  const std::optional<int> launched = mpiLaunchSize(processEnvironment());
  if (sharded || !launched || *launched < 2) return std::make_unique<LocalDistribution>();
  if (!mpiBuilt())
    throw InputError(SourceLocation{"lancer"},
                     fmt::format("this lancer was built without MPI (-DLANCER_MPI=OFF or no MPI found), but "
                                 "runs as one of {} processes under mpirun: each would render the whole "
                                 "job. Rebuild with libopenmpi-dev installed, or give --shard auto to "
                                 "split the frames",
                                 *launched));
  return makeMpiDistribution();
}

int commandThreads(int requested, const WorkDistribution& distribution) {
  return requested > 0 ? requested : distribution.defaultThreads();
}

}  // namespace lancer::cli
