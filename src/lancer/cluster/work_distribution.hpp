// Who renders which work item (a frame of an animation, a run of bands of a still) and where the
// results meet: one process renders them all in order (LocalDistribution), or the ranks of an MPI job
// share them and rank 0 receives them in order (mpi_distribution.hpp). Either way the items reach
// `deliver` in order 0, 1, 2, ..., so the output is the same bytes.
// Map: docs/architecture.md (the path of a ray through the modules).
#pragma once

#include <atomic>
#include <functional>

#include "lancer/image/image.hpp"

namespace lancer {

// Renders item `item`; may return early (an incomplete image) when the cancel flag is set.
using RenderItem = std::function<Image(int item)>;
// Receives item `item` on the delivering rank, in order.
using DeliverItem = std::function<void(int item, const Image& pixels)>;
// Items delivered so far of `total`, on the delivering rank, after each delivery.
using ItemProgress = std::function<void(int delivered, int total)>;

struct DistributedWork {
  int itemCount = 0;
  // The most items rendered but not yet delivered, rank 0's memory bound for a still's bands.
  int window = 1;
  RenderItem render;
  DeliverItem deliver;
  ItemProgress onDelivered;                   // optional
  const std::atomic<bool>* cancel = nullptr;  // optional: Ctrl-C, SIGTERM
};

class WorkDistribution {
 public:
  virtual ~WorkDistribution() = default;
  virtual int rank() const = 0;
  virtual int ranks() const = 0;
  // The only rank whose deliver is called: it writes the output and talks to the user.
  bool delivers() const { return rank() == 0; }
  // Threads for one rank's renders when the user gave no --threads: its share of the node's cores
  // (0: all of them, for a single process).
  virtual int defaultThreads() const = 0;
  // Renders and delivers every item; returns false when cancelled. An exception from render or
  // deliver propagates (on the rank where it happened).
  virtual bool run(const DistributedWork& work) = 0;
};

// One process: every item rendered here, in order.
class LocalDistribution final : public WorkDistribution {
 public:
  int rank() const override { return 0; }
  int ranks() const override { return 1; }
  int defaultThreads() const override { return 0; }
  bool run(const DistributedWork& work) override;
};

}  // namespace lancer
