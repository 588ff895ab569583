// For each vertex, the face corners that lie on it, in face order: the incidence that edge pairing
// (face_shells.hpp) and vertex normals (vertex_normals.hpp) walk vertex by vertex, so that their
// per-vertex work runs in parallel over vertex ranges and writes its results in order.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

struct VertexCorners {
  // Corners on vertex v: corner[rowStart[v] .. rowStart[v + 1]), each face << 2 | corner index,
  // increasing (face order, then corner order).
  std::vector<std::uint32_t> rowStart;
  std::vector<std::uint32_t> corner;
  std::size_t vertexCount() const { return rowStart.empty() ? 0 : rowStart.size() - 1; }
};

// `vertexCount`: at least one more than the largest vertex index of `faces`. With `wanted` (one flag
// per vertex), the rows of the other vertices are left empty. Same result for any thread count (0:
// every core).
VertexCorners findVertexCorners(std::span<const MeshFace> faces, std::size_t vertexCount, int threads,
                                std::span<const std::uint8_t> wanted = {});

// One more than the largest vertex index the faces use (0 for no faces).
std::size_t vertexCountOf(std::span<const MeshFace> faces, int threads);

}  // namespace lancer
