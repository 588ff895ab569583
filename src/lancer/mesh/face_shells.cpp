#include "lancer/mesh/face_shells.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "lancer/mesh/parity_disjoint_sets.hpp"
#include "lancer/mesh/vertex_corners.hpp"
#include "lancer/mesh/vertex_ranges.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer {
namespace {

// Vertices per chunk of the parallel loops.
constexpr std::size_t kGrain = 16384;

// Every face's edges grouped by key, in key order, and in face order among equal keys: a counting
// sort on the smaller vertex (one pass to count, one to scatter, in face order, each shared out by
// vertex ranges: vertex_ranges.hpp), then each vertex's few edges ordered by the larger vertex.
// Two passes over the edges where a radix sort on the 64-bit key took eight (Manifold pairs its
// half-edges the same way). The same table for any thread count.
std::vector<FaceEdge> sortedFaceEdges(std::span<const MeshFace> faces, int threads) {
  const std::size_t vertexCount = vertexCountOf(faces, threads);
  std::vector<std::uint32_t> bucketStart(vertexCount + 1, 0);
  forEachVertexRange(vertexCount, threads, [&](std::size_t firstVertex, std::size_t endVertex) {
    for (const MeshFace& face : faces) {
      const int n = face.cornerCount();
      for (int c = 0; c < n; ++c) {
        const std::uint32_t lo = std::min(face.vertex[c], face.vertex[(c + 1) % n]);
        if (lo >= firstVertex && lo < endVertex) ++bucketStart[lo + 1];
      }
    }
  });
  for (std::size_t v = 0; v < vertexCount; ++v) bucketStart[v + 1] += bucketStart[v];
  std::vector<FaceEdge> edges = vectorOnHugePages<FaceEdge>(bucketStart.back());  // 48 bytes per face
  std::vector<std::uint32_t> fill(bucketStart.begin(), bucketStart.end() - 1);
  forEachVertexRange(vertexCount, threads, [&](std::size_t firstVertex, std::size_t endVertex) {
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const MeshFace& face = faces[f];
      const int n = face.cornerCount();
      for (int c = 0; c < n; ++c) {
        const std::uint32_t a = face.vertex[c];
        const std::uint32_t b = face.vertex[(c + 1) % n];
        const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
        if (lo >= firstVertex && lo < endVertex)
          edges[fill[lo]++] = {(lo << 32) | hi, static_cast<std::uint32_t>(f), a < b};
      }
    }
  });
  // Within a bucket: stable insertion sort by key (a vertex has a handful of edges; a fan centre
  // with hundreds takes the library's stable sort).
  parallelFor(vertexCount, threads, kGrain, [&](std::size_t v) {
    FaceEdge* first = edges.data() + bucketStart[v];
    FaceEdge* last = edges.data() + bucketStart[v + 1];
    if (last - first > 32) {
      std::stable_sort(first, last);
      return;
    }
    for (FaceEdge* i = first + 1; i < last; ++i) {
      const FaceEdge e = *i;
      FaceEdge* j = i;
      for (; j > first && e.key < (j - 1)->key; --j) *j = *(j - 1);
      *j = e;
    }
  });
  return edges;
}

}  // namespace

FaceShells findFaceShells(std::span<const MeshFace> faces, int threads) {
  FaceShells result;
  const std::size_t faceCount = faces.size();
  result.edges = sortedFaceEdges(faces, threads);

  // Faces sharing an edge belong to one shell; an edge decides closedness and orientation. Two
  // faces on a manifold edge that traverse it the same way must be turned opposite ways for the
  // shell to agree (one parity constraint); at other edges the shell is open and no such bit holds.
  const std::vector<FaceEdge>& edges = result.edges;
  if (faceCount >= ParityDisjointSets::kMaxCount)
    throw std::length_error("findFaceShells: more than 2^31 faces in one mesh");
  ParityDisjointSets sets(faceCount);
  // Per face, what its edges told about its shell (one byte for the four, written rarely).
  enum : std::uint8_t { kOpen = 1, kMisoriented = 2, kBorder = 4, kBranch = 8 };
  std::vector<std::uint8_t> edgeFlags(faceCount, 0);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    if (j - i == 2) {
      const bool sameDirection = edges[i].forward == edges[i + 1].forward;
      if (edges[i].face != edges[i + 1].face)
        sets.unite(edges[i].face, edges[i + 1].face, sameDirection ? 1 : 0);
      if (sameDirection) edgeFlags[edges[i].face] |= kMisoriented;
    } else {
      for (std::size_t k = i + 1; k < j; ++k) sets.uniteFree(edges[i].face, edges[k].face);
      edgeFlags[edges[i].face] |= j - i == 1 ? kOpen | kBorder : kOpen | kMisoriented | kBranch;
    }
    i = j;
  }
  constexpr std::uint32_t kUnnumbered = 0xFFFFFFFFu;
  std::vector<std::uint32_t> shellOfRoot(faceCount, kUnnumbered);
  result.shellOfFace.resize(faceCount);
  result.flip.resize(faceCount);
  for (std::size_t f = 0; f < faceCount; ++f) {
    const auto [root, bit] = sets.find(static_cast<std::uint32_t>(f));
    std::uint32_t& shell = shellOfRoot[root];
    if (shell == kUnnumbered) {
      shell = static_cast<std::uint32_t>(result.closed.size());
      result.closed.push_back(1);
      result.consistent.push_back(1);
      result.orientable.push_back(sets.broken(root) ? 0 : 1);
      result.bordered.push_back(0);
      result.branched.push_back(0);
    }
    result.shellOfFace[f] = shell;
    result.flip[f] = bit;
    if (const std::uint8_t flags = edgeFlags[f]; flags != 0) {
      if (flags & kOpen) result.closed[shell] = 0;
      if (flags & kMisoriented) result.consistent[shell] = 0;
      if (flags & kBorder) result.bordered[shell] = 1;
      if (flags & kBranch) result.branched[shell] = 1;
    }
  }
  return result;
}

}  // namespace lancer
