// Counting sorts keyed by vertex (edges by their smaller end, corners by their vertex) run on
// several threads without atomics and without changing the result: the vertices are cut into one
// contiguous range per thread, and each thread walks all the faces in order but writes only the
// buckets of its own range. Every bucket is then filled in face order, as one thread would fill
// it, whatever the number of ranges; the faces are read once per thread, the scattered writes
// (the slow part) are shared out.
#pragma once

#include <algorithm>
#include <cstddef>

#include "lancer/util/parallel_for.hpp"
#include "lancer/util/thread_count.hpp"

namespace lancer {

// body(firstVertex, endVertex) for each range of [0, vertexCount), on up to `threads` threads.
template <typename Body>
void forEachVertexRange(std::size_t vertexCount, int threads, Body&& body) {
  // Small meshes, or many threads: reading every face once per range stops paying off.
  constexpr std::size_t kMinVerticesPerRange = 16384;
  constexpr std::size_t kMaxRanges = 8;
  const std::size_t ranges =
      std::clamp<std::size_t>(std::min<std::size_t>(static_cast<std::size_t>(resolveThreadCount(threads)),
                                                    vertexCount / kMinVerticesPerRange),
                              1, kMaxRanges);
  parallelChunks(ChunkPlan(ranges, 1), threads, [&](std::size_t range, std::size_t, std::size_t) {
    body(vertexCount * range / ranges, vertexCount * (range + 1) / ranges);
  });
}

}  // namespace lancer
