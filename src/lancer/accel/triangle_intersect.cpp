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

}  // namespace lancer
