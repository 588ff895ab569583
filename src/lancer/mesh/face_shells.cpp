#include "lancer/mesh/face_shells.hpp"

#include <algorithm>
#include <utility>

#include "lancer/mesh/disjoint_sets.hpp"

namespace lancer {
namespace {

// Every face's edges grouped by key, in key order, and in face order among equal keys: a counting
// sort on the smaller vertex (one pass to count, one to scatter, in face order), then each
// vertex's few edges ordered by the larger vertex. Two passes over the edges where a radix sort on
// the 64-bit key took eight (Manifold pairs its half-edges the same way).
std::vector<FaceEdge> sortedFaceEdges(const std::vector<MeshFace>& faces) {
  std::uint32_t vertexCount = 0;
  std::size_t edgeCount = 0;
  for (const MeshFace& face : faces) {
    for (int c = 0; c < face.cornerCount(); ++c) vertexCount = std::max(vertexCount, face.vertex[c] + 1);
    edgeCount += static_cast<std::size_t>(face.cornerCount());
  }
  std::vector<std::uint32_t> bucketStart(std::size_t(vertexCount) + 1, 0);
  for (const MeshFace& face : faces) {
    const int n = face.cornerCount();
    for (int c = 0; c < n; ++c) ++bucketStart[std::min(face.vertex[c], face.vertex[(c + 1) % n]) + 1];
  }
  for (std::size_t v = 0; v < vertexCount; ++v) bucketStart[v + 1] += bucketStart[v];
  std::vector<FaceEdge> edges(edgeCount);
  std::vector<std::uint32_t> fill(bucketStart.begin(), bucketStart.end() - 1);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const MeshFace& face = faces[f];
    const int n = face.cornerCount();
    for (int c = 0; c < n; ++c) {
      const std::uint32_t a = face.vertex[c];
      const std::uint32_t b = face.vertex[(c + 1) % n];
      const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
      edges[fill[lo]++] = {(lo << 32) | hi, static_cast<std::uint32_t>(f), a < b};
    }
  }
  // Within a bucket: stable insertion sort by key (a vertex has a handful of edges; a fan centre
  // with hundreds takes the library's stable sort).
  for (std::size_t v = 0; v < vertexCount; ++v) {
    FaceEdge* first = edges.data() + bucketStart[v];
    FaceEdge* last = edges.data() + bucketStart[v + 1];
    if (last - first > 32) {
      std::stable_sort(first, last);
      continue;
    }
    for (FaceEdge* i = first + 1; i < last; ++i) {
      const FaceEdge e = *i;
      FaceEdge* j = i;
      for (; j > first && e.key < (j - 1)->key; --j) *j = *(j - 1);
      *j = e;
    }
  }
  return edges;
}

}  // namespace

FaceShells findFaceShells(const std::vector<MeshFace>& faces) {
  FaceShells result;
  const std::size_t faceCount = faces.size();
  result.edges = sortedFaceEdges(faces);

  // Faces sharing an edge belong to one shell; an edge decides closedness and orientation.
  const std::vector<FaceEdge>& edges = result.edges;
  DisjointSets sets(faceCount);
  std::vector<std::uint8_t> edgeOpen(faceCount, 0), edgeMisoriented(faceCount, 0);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    for (std::size_t k = i + 1; k < j; ++k) sets.unite(edges[i].face, edges[k].face);
    if (j - i != 2) edgeOpen[edges[i].face] = 1;
    if (j - i > 2 || (j - i == 2 && edges[i].forward == edges[i + 1].forward))
      edgeMisoriented[edges[i].face] = 1;
    i = j;
  }
  constexpr std::uint32_t kUnnumbered = 0xFFFFFFFFu;
  std::vector<std::uint32_t> shellOfRoot(faceCount, kUnnumbered);
  result.shellOfFace.resize(faceCount);
  for (std::size_t f = 0; f < faceCount; ++f) {
    std::uint32_t& shell = shellOfRoot[sets.find(static_cast<std::uint32_t>(f))];
    if (shell == kUnnumbered) {
      shell = static_cast<std::uint32_t>(result.closed.size());
      result.closed.push_back(1);
      result.consistent.push_back(1);
    }
    result.shellOfFace[f] = shell;
    if (edgeOpen[f]) result.closed[shell] = 0;
    if (edgeMisoriented[f]) result.consistent[shell] = 0;
  }
  return result;
}

}  // namespace lancer
