// Smooth vertex normals for Gouraud and Phong shading: the angle-weighted average of the normals of
// the faces around a vertex, split where faces meet at a crease or a physical-group boundary.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

struct CornerNormals {
  std::vector<Vec3> normals;                             // unit vectors, shared by corners that agree
  std::vector<std::array<std::uint32_t, 4>> faceCorner;  // per face, per corner: index into normals
};

// Two faces sharing a vertex are smoothed together when the angle between their normals is at most
// creaseAngleDegrees and they have the same physical tag (Thurmer & Wuthrich 1998 angle weights).
// On `threads` threads (0: every core); the result is the same for any number. The unit face
// normals it works from (faceNormal of face_geometry.hpp) go to `unitFaceNormals` when given.
CornerNormals computeCornerNormals(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                                   std::span<const std::int32_t> facePhysicalTag, float creaseAngleDegrees,
                                   int threads = 0, std::vector<Vec3>* unitFaceNormals = nullptr);

}  // namespace lancer
