#include "lancer/accel/triangle_intersect.hpp"

namespace lancer {

std::vector<PackedTriangle> packTriangles(std::span<const Vec3> positions, std::span<const MeshFace> faces) {
  std::vector<PackedTriangle> triangles;
  triangles.reserve(faces.size() * 2);
  auto pack = [&](std::uint32_t face, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    triangles.push_back({positions[a], positions[b], positions[c], face});
  };
  for (std::uint32_t f = 0; f < faces.size(); ++f) {
    const MeshFace& face = faces[f];
    pack(f, face.vertex[0], face.vertex[1], face.vertex[2]);
    if (face.isQuad()) pack(f, face.vertex[0], face.vertex[2], face.vertex[3]);
  }
  return triangles;
}

bool isSliverTriangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  constexpr double kSliverSine = 1e-4;
  // Most triangles are far from slivers, which float arithmetic settles: its rounding (a few 1e-7 of
  // |e1| |e2| in the cross product's length) is a thousandth of the margin of twice the sine.
  const Vec3 f1 = b - a, f2 = c - a, fn = cross(f1, f2);
  constexpr auto kClearly = static_cast<float>(4.0 * kSliverSine * kSliverSine);
  if (dot(fn, fn) > kClearly * dot(f1, f1) * dot(f2, f2)) return false;
  const Vec3d e1 = toDouble(b) - toDouble(a);
  const Vec3d e2 = toDouble(c) - toDouble(a);
  const Vec3d n = cross(e1, e2);
  return dot(n, n) <= kSliverSine * kSliverSine * dot(e1, e1) * dot(e2, e2);
}

}  // namespace lancer
