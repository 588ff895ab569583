#include "lancer/mesh/feature_edges.hpp"

#include <algorithm>
#include <cmath>

namespace lancer {
namespace {

struct EdgeUse {
  std::uint64_t key;  // (smaller vertex << 32) | larger vertex
  std::uint32_t face;
  std::uint8_t corner;
};

// Newell's normal: also right for a slightly non-planar quad. The same vector as face_geometry.hpp's
// faceNormal in exact arithmetic, but not in float: where a crease is exactly the feature angle
// (render/bracket_coarse.msh and bracket_zup.msh at 45 degrees) the rounding decides, and the other
// formula draws other edges there; so this one stays, to keep the pictures.
Vec3 newellNormal(const Mesh& mesh, const MeshFace& face) {
  Vec3 normal{0, 0, 0};
  const int n = face.cornerCount();
  for (int i = 0; i < n; ++i) {
    const Vec3& p = mesh.positions[face.vertex[i]];
    const Vec3& q = mesh.positions[face.vertex[(i + 1) % n]];
    normal += Vec3{(p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y)};
  }
  const float len = length(normal);
  return len > 0.0f ? normal * (1.0f / len) : normal;
}

}  // namespace

std::vector<std::uint8_t> featureEdgeMasks(const Mesh& mesh, float creaseDegrees) {
  const std::size_t faceCount = mesh.faces.size();
  std::vector<Vec3> normals(faceCount);
  std::vector<EdgeUse> uses;
  uses.reserve(faceCount * 4);
  for (std::uint32_t f = 0; f < faceCount; ++f) {
    const MeshFace& face = mesh.faces[f];
    normals[f] = newellNormal(mesh, face);
    const int n = face.cornerCount();
    for (int i = 0; i < n; ++i) {
      const std::uint64_t a = face.vertex[i], b = face.vertex[(i + 1) % n];
      uses.push_back({std::min(a, b) << 32 | std::max(a, b), f, static_cast<std::uint8_t>(i)});
    }
  }
  // Sorting groups the uses of each edge; O(E log E) and no hash map to allocate per edge.
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.key != y.key ? x.key < y.key : x.face < y.face;
  });

  const float cosCrease = std::cos(creaseDegrees * 3.14159265358979f / 180.0f);
  std::vector<std::uint8_t> masks(faceCount, 0);
  for (std::size_t begin = 0; begin < uses.size();) {
    std::size_t end = begin + 1;
    while (end < uses.size() && uses[end].key == uses[begin].key) ++end;
    bool feature = end - begin != 2;  // boundary or non-manifold
    if (!feature) {
      const EdgeUse &x = uses[begin], &y = uses[begin + 1];
      // Normals of consistently wound neighbours agree; a flipped neighbour is still smooth, so
      // compare the angle between the face planes (|cos|), not between the oriented normals.
      const bool otherGroup = mesh.facePhysicalTag[x.face] != mesh.facePhysicalTag[y.face];
      const bool crease = std::abs(dot(normals[x.face], normals[y.face])) < cosCrease;
      feature = otherGroup || crease;
    }
    if (feature)
      for (std::size_t u = begin; u < end; ++u)
        masks[uses[u].face] |= static_cast<std::uint8_t>(1u << uses[u].corner);
    begin = end;
  }
  for (std::size_t f = 0; f < faceCount; ++f)
    if (f < mesh.faceEdgeMask.size()) masks[f] &= mesh.faceEdgeMask[f];
  return masks;
}

}  // namespace lancer
