#include "lancer/mesh/vertex_corners.hpp"

#include <algorithm>

#include "lancer/mesh/prefetch_corners.hpp"
#include "lancer/mesh/vertex_ranges.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer {
namespace {

// Faces or vertices per chunk of the parallel loops: a chunk outweighs handing it out.
constexpr std::size_t kGrain = 32768;

}  // namespace

std::size_t vertexCountOf(std::span<const MeshFace> faces, int threads) {
  const ChunkPlan plan(faces.size(), kGrain);
  std::vector<std::uint32_t> chunkEnd(plan.chunks, 0);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::uint32_t count = 0;
    for (std::size_t f = begin; f < end; ++f)
      for (int c = 0; c < faces[f].cornerCount(); ++c) count = std::max(count, faces[f].vertex[c] + 1);
    chunkEnd[chunk] = count;
  });
  return faces.empty() ? 0 : *std::max_element(chunkEnd.begin(), chunkEnd.end());
}

VertexCorners findVertexCorners(std::span<const MeshFace> faces, std::size_t vertexCount, int threads,
                                std::span<const std::uint8_t> wanted) {
  VertexCorners result;
  auto inRange = [&](std::uint32_t v, std::size_t firstVertex, std::size_t endVertex) {
    return v >= firstVertex && v < endVertex && (wanted.empty() || wanted[v]);
  };
  result.rowStart.assign(vertexCount + 1, 0);
  forEachVertexRange(vertexCount, threads, [&](std::size_t firstVertex, std::size_t endVertex) {
    for (std::size_t f = 0; f < faces.size(); ++f) {
      prefetchCorners(result.rowStart.data() + 1, faces, f + kPrefetchFacesAhead);
      const MeshFace& face = faces[f];
      for (int c = 0; c < face.cornerCount(); ++c)
        if (inRange(face.vertex[c], firstVertex, endVertex)) ++result.rowStart[face.vertex[c] + 1];
    }
  });
  for (std::size_t v = 0; v < vertexCount; ++v) result.rowStart[v + 1] += result.rowStart[v];
  result.corner.resize(result.rowStart.back());
  std::vector<std::uint32_t> fill(result.rowStart.begin(), result.rowStart.end() - 1);
  forEachVertexRange(vertexCount, threads, [&](std::size_t firstVertex, std::size_t endVertex) {
    for (std::size_t f = 0; f < faces.size(); ++f) {
      prefetchCorners(fill.data(), faces, f + kPrefetchFacesAhead);
      for (int c = 0; c < faces[f].cornerCount(); ++c) {
        const std::uint32_t v = faces[f].vertex[c];
        if (inRange(v, firstVertex, endVertex))
          result.corner[fill[v]++] = static_cast<std::uint32_t>(f) << 2 | static_cast<std::uint32_t>(c);
      }
    }
  });
  return result;
}

}  // namespace lancer
