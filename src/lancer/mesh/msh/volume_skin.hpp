// Volume elements become their boundary: every element face is listed with outward winding; the
// faces that occur exactly once are the skin, and the faces shared by elements of two different
// volumes are the interfaces between them.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"

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

// The i-th node of a volume face in the order corner[0..3], mid[0..3], centre.
inline std::uint32_t volumeFaceNode(const MshVolumeFace& face, int i) {
  return i < 4 ? face.corner[i] : i < 8 ? face.mid[i - 4] : face.centre;
}

// The shape of a gmsh volume element type of any order, or nullopt for any other type.
std::optional<CellShape> mshVolumeShape(int type);

// Appends the faces of a volume element (any type mshVolumeShape knows; others add nothing).
void appendVolumeElementFaces(int type, const std::uint32_t* nodes, std::uint32_t group,
                              std::vector<MshVolumeFace>& faces);

// One face of the volumes' boundary: `face` (an index into the volume faces) is the side kept, wound
// out of its element's volume; `outer` is the face of the other volume's element on an interface,
// kNoVertex on the skin.
struct VolumeBoundaryFace {
  std::uint32_t face;
  std::uint32_t outer;
};

// The faces that occur once among `faces` (skin) and the faces that occur twice with two different
// volumes (volumeOfGroup[face.group], any 64-bit identity per group); faces shared by two elements
// of one volume, or by more than two elements, are interior. On an interface the kept side is the
// element of the smaller volume identity. `severalVolumes` false: every face is of one volume (then
// there are no interfaces, and the sort moves smaller entries). Ascending by `face`. O(n log n): one
// sort of the keys.
std::vector<VolumeBoundaryFace> findVolumeBoundary(std::span<const MshVolumeFace> faces,
                                                   std::span<const std::uint64_t> volumeOfGroup,
                                                   bool severalVolumes);

}  // namespace lancer
