// Internal to the .msh reader: triangles and quadrangles of order 3 and up (gmsh -order 3 and
// higher), split into flat faces through their nodes. gmsh orders a complete element's nodes
// recursively (gmsh manual, "High-order elements"): corners, then each edge's nodes from its first
// corner, then the interior nodes as an element of the order lower by 3 (triangle) or 2 (quad).
#pragma once

#include <cstdint>
#include <vector>

namespace lancer {

// One face of a split element: local node indices (corner[3] == kNoSubCorner for a triangle) and
// which of its edges lie on the element's edges (bit i: corner i to i+1, as Mesh::faceEdgeMask).
inline constexpr std::uint16_t kNoSubCorner = 0xFFFF;
struct MshSubFace {
  std::uint16_t corner[4];
  std::uint8_t edgeMask;
};

// The faces a triangle or quadrangle of type `type` is drawn as: through all its nodes for complete
// elements of order 3 to 10, through its corners for the incomplete (serendipity) ones; empty for
// any other type. Computed once per type.
const std::vector<MshSubFace>& mshHighOrderSurfaceFaces(int type);

}  // namespace lancer
