#include "lancer/scene/face_elements.hpp"

#include <unordered_map>

#include "lancer/mesh/disjoint_sets.hpp"

namespace lancer {

FaceElements faceElements(const Mesh& mesh) {
  const std::size_t faceCount = mesh.faces.size();
  DisjointSets sets(faceCount);
  // Faces meet along an edge of no element only inside a split second-order element: join them.
  const bool masked = mesh.faceEdgeMask.size() == faceCount;
  std::unordered_map<std::uint64_t, std::uint32_t> innerEdges;
  for (std::uint32_t f = 0; masked && f < faceCount; ++f) {
    const MeshFace& face = mesh.faces[f];
    const int n = face.cornerCount();
    for (int c = 0; c < n; ++c) {
      if (mesh.faceEdgeMask[f] & (1u << c)) continue;
      const std::uint32_t a = face.vertex[c], b = face.vertex[(c + 1) % n];
      const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
      const auto [it, inserted] = innerEdges.try_emplace(key, f);
      if (!inserted) sets.unite(it->second, f);
    }
  }
  FaceElements elements;
  elements.ofFace.resize(faceCount);
  // The smallest face of each set is its root: elements are numbered in the order of their first face.
  for (std::uint32_t f = 0; f < faceCount; ++f) {
    const std::uint32_t root = sets.find(f);
    if (root == f) {
      elements.ofFace[f] = static_cast<std::uint32_t>(elements.first.size());
      elements.first.push_back(f);
    } else {
      elements.ofFace[f] = elements.ofFace[root];
    }
  }
  return elements;
}

ElementCentroids elementCentroids(const Mesh& mesh, const FaceElements& elements,
                                  const std::vector<Vec3d>& positions) {
  ElementCentroids out;
  out.centroid.assign(elements.count(), Vec3d{0, 0, 0});
  out.area.assign(elements.count(), 0.0);
  std::vector<Vec3d> cornerMean(elements.count(), Vec3d{0, 0, 0});
  std::vector<int> corners(elements.count(), 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const MeshFace& face = mesh.faces[f];
    const std::uint32_t e = elements.ofFace[f];
    // A quad as the two triangles about its first corner: their centroids weighted by their areas.
    for (int t = 0; t + 2 < face.cornerCount(); ++t) {
      const Vec3d& p = positions[face.vertex[0]];
      const Vec3d& q = positions[face.vertex[t + 1]];
      const Vec3d& r = positions[face.vertex[t + 2]];
      const double area = 0.5 * length(cross(q - p, r - p));
      out.centroid[e] = out.centroid[e] + (p + q + r) * (area / 3);
      out.area[e] += area;
    }
    for (int c = 0; c < face.cornerCount(); ++c) cornerMean[e] = cornerMean[e] + positions[face.vertex[c]];
    corners[e] += face.cornerCount();
  }
  for (std::size_t e = 0; e < elements.count(); ++e)
    out.centroid[e] =
        out.area[e] > 0 ? out.centroid[e] * (1 / out.area[e]) : cornerMean[e] * (1.0 / corners[e]);
  return out;
}

}  // namespace lancer
