#include "lancer/mesh/face_shells.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "lancer/mesh/disjoint_sets.hpp"

namespace lancer {
namespace {

// LSD radix sort by key, 11 bits a pass over the bits the keys use (twice the vertex index width):
// std::sort of the 3 edges per face took a quarter of a million-triangle mesh's preparation.
// Stable, so the result is as deterministic as the input.
void sortEdgesByKey(std::vector<FaceEdge>& edges) {
  if (edges.size() < 4096) {
    std::sort(edges.begin(), edges.end());
    return;
  }
  std::uint64_t all = 0;
  for (const FaceEdge& e : edges) all |= e.key;
  constexpr int kBits = 11;
  constexpr std::size_t kBuckets = std::size_t(1) << kBits;
  std::vector<FaceEdge> buffer(edges.size());
  std::vector<std::size_t> count(kBuckets);
  for (int shift = 0; shift < 64 && (all >> shift) != 0; shift += kBits) {
    // Skip a digit every key has equal (the high vertex word of small meshes).
    if (((all >> shift) & (kBuckets - 1)) == 0) continue;
    std::fill(count.begin(), count.end(), 0);
    for (const FaceEdge& e : edges) ++count[(e.key >> shift) & (kBuckets - 1)];
    std::size_t sum = 0;
    for (std::size_t& c : count) sum += std::exchange(c, sum);
    for (const FaceEdge& e : edges) buffer[count[(e.key >> shift) & (kBuckets - 1)]++] = e;
    edges.swap(buffer);
  }
}

}  // namespace

FaceShells findFaceShells(const std::vector<MeshFace>& faces) {
  FaceShells result;
  const std::size_t faceCount = faces.size();
  result.edges.reserve(faceCount * 4);
  for (std::size_t f = 0; f < faceCount; ++f) {
    const MeshFace& face = faces[f];
    const int n = face.cornerCount();
    for (int c = 0; c < n; ++c) {
      const std::uint32_t a = face.vertex[c];
      const std::uint32_t b = face.vertex[(c + 1) % n];
      const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
      result.edges.push_back({(lo << 32) | hi, static_cast<std::uint32_t>(f), a < b});
    }
  }
  sortEdgesByKey(result.edges);

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
  std::map<std::uint32_t, std::uint32_t> shellOfRoot;
  result.shellOfFace.resize(faceCount);
  for (std::size_t f = 0; f < faceCount; ++f) {
    const std::uint32_t root = sets.find(static_cast<std::uint32_t>(f));
    auto [it, inserted] = shellOfRoot.emplace(root, static_cast<std::uint32_t>(result.closed.size()));
    if (inserted) {
      result.closed.push_back(1);
      result.consistent.push_back(1);
    }
    result.shellOfFace[f] = it->second;
    if (edgeOpen[f]) result.closed[it->second] = 0;
    if (edgeMisoriented[f]) result.consistent[it->second] = 0;
  }
  return result;
}

}  // namespace lancer
