// Volume elements become their skin: every element face is listed with outward winding, and the
// faces that occur exactly once (and are not already a surface element) are the boundary.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

// One face of a volume element, wound outward for a positively oriented element. For second-order
// tetrahedra and hexahedra, mid[] holds the face's edge nodes (corner0-corner1, corner1-corner2, ...)
// and centre a 27-node hexahedron's face node, so the skin is split like a 6-node triangle or a
// 9-node quad (an 8-node quad when centre is kNoVertex); mid[0] == kNoVertex otherwise (prisms and
// pyramids of second order use their corners only).
struct MshVolumeFace {
  std::uint32_t corner[4];
  std::uint32_t mid[4];
  std::uint32_t centre;
  std::uint32_t group;  // index into the assembler's (physical, entity) table
};

using MshFaceKey = std::array<std::uint32_t, 4>;  // sorted corner indices, kNoVertex last for triangles

MshFaceKey mshFaceKey(const std::uint32_t* corners, int cornerCount);

// Appends the faces of a volume element of gmsh type 4-7, 11-14 or 17-19.
void appendVolumeElementFaces(int type, const std::uint32_t* nodes, std::uint32_t group,
                              std::vector<MshVolumeFace>& faces);

// Indices (ascending) of the faces that occur once among `faces` and whose key is not in
// surfaceKeys (sorted). coveredBySurface counts the once-only faces a surface element already shows.
std::vector<std::uint32_t> findSkinFaces(std::span<const MshVolumeFace> faces,
                                         std::span<const MshFaceKey> surfaceKeys,
                                         std::uint64_t& coveredBySurface);

}  // namespace lancer
