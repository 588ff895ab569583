// The closed regions of a surface whose faces meet three or more on an edge (two boxes drawn with
// their shared wall once, as a 2D mesh of gmsh fragments gives): without volume elements, which
// side of each face is which region is found from the order of the faces around each edge.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lancer/mesh/face_shells.hpp"
#include "lancer/mesh/mesh.hpp"

namespace lancer {

inline constexpr std::uint32_t kNoRegion = 0xFFFFFFFFu;

// Per face: the region in front of it (where its normal points) and the one behind it, kNoRegion
// for faces of other shells; per region, whether it is bounded (enclosed: positive volume) or the
// outside.
struct ShellRegions {
  std::vector<std::uint32_t> front, back;  // per face
  std::vector<std::uint8_t> bounded;       // per region
  bool empty() const { return bounded.empty(); }
};

// The regions of every shell of `shells` that has an edge of three or more faces and none of one
// face (a closed, non-manifold surface). Around each such edge the faces are ordered by angle
// (in double); the two sides that face each other across the wedge between
// neighbouring faces are one region; a shell is left out (its faces kNoRegion) when two faces around
// an edge lie at the same angle or its regions are not one outside and bounded cells. O(faces of
// those shells).
ShellRegions findShellRegions(std::span<const Vec3> positions, const std::vector<MeshFace>& faces,
                              const FaceShells& shells);

}  // namespace lancer
