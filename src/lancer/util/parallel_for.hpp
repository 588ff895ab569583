// Data-parallel loops for scene preparation: [0, count) cut into contiguous chunks, each run by one
// thread. The chunks depend on the count alone, never on the thread count, so a loop whose chunks
// write disjoint results gives the same bytes on 1 thread as on 16.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

#include "lancer/util/thread_count.hpp"

namespace lancer {

// Chunk k covers [chunkBegin(k), chunkBegin(k + 1)); chunks of at least `grain` items.
struct ChunkPlan {
  std::size_t count = 0;
  std::size_t chunks = 1;
  ChunkPlan(std::size_t itemCount, std::size_t grain)
      : count(itemCount),
        chunks(std::max<std::size_t>(
            1, std::min<std::size_t>(64, itemCount / std::max<std::size_t>(grain, 1)))) {}
  std::size_t begin(std::size_t chunk) const { return count * chunk / chunks; }
};

// Runs body(chunk, begin, end) for every chunk of the plan on up to `threads` threads (0: every
// core), the calling thread included; returns when all are done. An exception in a body is
// rethrown here (the first one; the other chunks still run).
template <typename Body>
void parallelChunks(const ChunkPlan& plan, int threads, Body&& body) {
  const auto workers = static_cast<std::size_t>(
      std::min<std::size_t>(static_cast<std::size_t>(resolveThreadCount(threads)), plan.chunks));
  if (workers <= 1) {
    for (std::size_t k = 0; k < plan.chunks; ++k) body(k, plan.begin(k), plan.begin(k + 1));
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::atomic<bool> failed{false};
  auto work = [&] {
    for (std::size_t k; (k = next.fetch_add(1)) < plan.chunks;) {
      try {
        body(k, plan.begin(k), plan.begin(k + 1));
      } catch (...) {
        if (!failed.exchange(true)) failure = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(workers - 1);
  for (std::size_t t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (std::thread& thread : pool) thread.join();
  if (failure) std::rethrow_exception(failure);
}

// body(i) for every i in [0, count), in chunks of at least `grain`.
template <typename Body>
void parallelFor(std::size_t count, int threads, std::size_t grain, Body&& body) {
  parallelChunks(ChunkPlan(count, grain), threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) body(i);
  });
}

}  // namespace lancer
