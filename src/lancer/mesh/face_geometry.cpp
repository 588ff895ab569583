#include "lancer/mesh/face_geometry.hpp"

#include <algorithm>

namespace lancer {

Vec3d twiceVectorArea(std::span<const Vec3> positions, const MeshFace& face) {
  const Vec3d a = toDouble(positions[face.vertex[0]]);
  const Vec3d b = toDouble(positions[face.vertex[1]]);
  const Vec3d c = toDouble(positions[face.vertex[2]]);
  if (!face.isQuad()) return cross(b - a, c - a);
  const Vec3d d = toDouble(positions[face.vertex[3]]);
  return cross(c - a, d - b);
}

double faceArea(std::span<const Vec3> positions, const MeshFace& face) {
  return 0.5 * length(twiceVectorArea(positions, face));
}

double sixfoldConeVolume(std::span<const Vec3> positions, const MeshFace& face) {
  const Vec3d a = toDouble(positions[face.vertex[0]]);
  double volume = 0;
  for (int c = 1; c + 1 < face.cornerCount(); ++c)
    volume += dot(a, cross(toDouble(positions[face.vertex[c]]), toDouble(positions[face.vertex[c + 1]])));
  return volume;
}

void reverseWinding(MeshFace& face, std::uint8_t& edgeMask) {
  // (v0, v1, ..., v{n-1}) becomes (v0, v{n-1}, ..., v1): new edge i is old edge n-1-i, reversed.
  const int n = face.cornerCount();
  std::reverse(face.vertex + 1, face.vertex + n);
  std::uint8_t mask = 0;
  for (int i = 0; i < n; ++i)
    if (edgeMask & (1u << (n - 1 - i))) mask |= static_cast<std::uint8_t>(1u << i);
  edgeMask = static_cast<std::uint8_t>(mask | (edgeMask & ~((1u << n) - 1u)));
}

}  // namespace lancer
