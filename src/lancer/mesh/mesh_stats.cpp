#include "lancer/mesh/mesh_stats.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "lancer/mesh/shell_nesting.hpp"

namespace lancer {
namespace {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::uint32_t> parent_;
};

Vec3d localPosition(const Mesh& mesh, std::uint32_t vertex) { return toDouble(mesh.positions[vertex]); }

// Signed volume of the cone from the origin over the face (triangles fanned from corner 0).
double coneVolume(const Mesh& mesh, const MeshFace& face) {
  const Vec3d a = localPosition(mesh, face.vertex[0]);
  double volume = 0;
  for (int c = 1; c + 1 < face.cornerCount(); ++c)
    volume +=
        dot(a, cross(localPosition(mesh, face.vertex[c]), localPosition(mesh, face.vertex[c + 1]))) / 6.0;
  return volume;
}

}  // namespace

double faceArea(const Mesh& mesh, std::size_t f) {
  const MeshFace& face = mesh.faces[f];
  const Vec3d a = localPosition(mesh, face.vertex[0]);
  const Vec3d b = localPosition(mesh, face.vertex[1]);
  const Vec3d c = localPosition(mesh, face.vertex[2]);
  if (!face.isQuad()) return 0.5 * length(cross(b - a, c - a));
  const Vec3d d = localPosition(mesh, face.vertex[3]);
  return 0.5 * length(cross(c - a, d - b));
}

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

MeshStats computeMeshStats(const Mesh& mesh) {
  MeshStats stats;
  const std::size_t faceCount = mesh.faces.size();
  for (std::size_t f = 0; f < faceCount; ++f) {
    const MeshFace& face = mesh.faces[f];
    face.isQuad() ? ++stats.quads : ++stats.triangles;
    stats.area += faceArea(mesh, f);
    ++stats.facesByPhysicalTag[mesh.facePhysicalTag[f]];
    if (const std::vector<std::int32_t>* more = mesh.morePhysicalTags(f))
      for (const std::int32_t tag : *more) ++stats.facesByPhysicalTag[tag];
    if (mesh.volumeSides.isInterface(f)) {
      const std::int32_t inner = mesh.facePhysicalTag[f], outer = mesh.volumeSides.outerPhysicalTag[f];
      if (outer != inner) ++stats.facesByPhysicalTag[outer];
      ++stats.interfaceFacesByPhysicalTag[inner];
      if (outer != inner) ++stats.interfaceFacesByPhysicalTag[outer];
      const std::int64_t a = inner != 0 ? inner : -std::int64_t{mesh.faceEntityTag[f]};
      const std::int64_t b = outer != 0 ? outer : -std::int64_t{mesh.volumeSides.outerEntityTag[f]};
      ++stats.interfaces[{std::min(a, b), std::max(a, b)}];
    }
    for (int c = 0; c < face.cornerCount(); ++c) stats.worldBounds.extend(mesh.worldPosition(face.vertex[c]));
  }
  const FaceShells faceShells = findFaceShells(mesh.faces);
  std::vector<MeshShell> shells(faceShells.shellCount());
  for (std::size_t f = 0; f < faceCount; ++f) {
    MeshShell& shell = shells[faceShells.shellOfFace[f]];
    ++shell.faceCount;
    shell.area += faceArea(mesh, f);
    shell.signedVolume += coneVolume(mesh, mesh.faces[f]);
  }
  std::vector<std::uint8_t> solid(shells.size(), 0);
  for (std::size_t s = 0; s < shells.size(); ++s) {
    shells[s].closed = faceShells.closed[s] != 0;
    shells[s].consistentlyOriented = faceShells.consistent[s] != 0;
    solid[s] = shells[s].closed && shells[s].consistentlyOriented;
  }
  const std::vector<std::uint8_t> cavity =
      findCavityShells(mesh.positions, mesh.faces, faceShells, mesh.facePhysicalTag, solid);
  for (std::size_t f = 0; f < faceCount; ++f)
    if (mesh.volumeSides.isInterface(f)) shells[faceShells.shellOfFace[f]].interface = true;
  for (std::size_t s = 0; s < shells.size(); ++s) shells[s].cavity = cavity[s] != 0 && !shells[s].interface;
  std::stable_sort(shells.begin(), shells.end(),
                   [](const MeshShell& a, const MeshShell& b) { return a.faceCount > b.faceCount; });
  stats.shells = std::move(shells);
  return stats;
}

}  // namespace lancer
