// Work items shared by the ranks of an MPI job (Open MPI's mpirun): rank 0 hands items out
// one at a time as ranks ask (dynamic balance), renders items itself between hand-outs, and delivers
// every result in order. Waiting ranks sleep between MPI_Test calls instead of spinning in a blocking
// call (Open MPI busy-polls there), so a rank's cores stay with its render threads.
#pragma once

#include <memory>
#include <optional>

#include "lancer/cluster/shard.hpp"
#include "lancer/cluster/work_distribution.hpp"

namespace lancer {

// Whether this lancer was built with MPI (LANCER_MPI, on when CMake finds MPI).
bool mpiBuilt();

// The number of processes a launcher started this job as (OMPI_COMM_WORLD_SIZE from Open MPI's
// mpirun, PMI_SIZE from a PMI launcher), nullopt when none did.
std::optional<int> mpiLaunchSize(const EnvironmentLookup& environment);

// Initialises MPI (once) and returns the distribution over MPI_COMM_WORLD. Only when mpiBuilt().
std::unique_ptr<WorkDistribution> makeMpiDistribution();

// "rank 2 of 4" once MPI is initialised, else "": the prefix for a rank's error messages.
std::string mpiRankLabel();

// At the end of the process: with exit code 0 waits (sleeping, not spinning) for every rank and
// finalises MPI. Otherwise the job must end: rank 0 aborts it; another rank exits without
// finalising, and the launcher ends the others (rank 0 by SIGTERM, so it removes its temporary
// files). Does nothing when MPI was never initialised.
void endMpi(int exitCode);

}  // namespace lancer
