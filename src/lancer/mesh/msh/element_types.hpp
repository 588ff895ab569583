// The gmsh element types (MSH "elm-type" numbers): how many nodes each has and what lancer makes of
// it (faces, a volume's skin, nothing, or "cannot render"). Numbers from gmsh's GmshDefines.h.
#pragma once

#include <cstdint>
#include <string>

namespace lancer {

enum class MshElementRole : std::uint8_t {
  kIgnored,       // points and lines: not surfaces, silently skipped (still counted as read)
  kSurface,       // triangles and quads of any order: become faces (high_order.hpp for order 3+)
  kVolume,        // tetrahedra, hexahedra, prisms, pyramids of any order: become their skin
  kUnrenderable,  // polygons, polyhedra, one-node "elements", trihedra: counted and reported
};

struct MshElementType {
  int nodeCount = 0;  // 0: unknown or variable-size type, which no reader here can skip
  int dimension = 0;
  MshElementRole role = MshElementRole::kIgnored;
};

inline constexpr int kMaxMshElementType = 140;
inline constexpr int kMaxMshElementNodes = 1000;  // MSH_HEX_1000

// The type's description; nodeCount == 0 when lancer does not know the type.
MshElementType mshElementType(int type);

// Tetrahedra, hexahedra, prisms and pyramids of first and second order (types 4-7, 11-14, 17-19):
// the volumes whose skin keeps their edge nodes, and the bulk of every volume mesh.
inline constexpr bool mshIsLowOrderVolume(int type) {
  return (type >= 4 && type <= 7) || (type >= 11 && type <= 14) || (type >= 17 && type <= 19);
}

// "3-node triangle", "10-node tetrahedron", ... for `lancer info`; "type N" for rare ones.
std::string mshElementTypeName(int type);

// The order p of a complete triangle or quadrangle of order 3 to 10 (gmsh's MSH_TRI_10 ... MSH_TRI_66,
// MSH_QUA_16 ... MSH_QUA_121), 0 for any other type.
int mshCompleteSurfaceOrder(int type);

// 3 for a drawn triangle type, 4 for a drawn quadrangle type, 0 for anything else.
int mshSurfaceCorners(int type);

// How lancer draws elements of order 3 and up, for `lancer info` ("subdivided through all its
// nodes", "drawn through its corner nodes"); "" for the others.
std::string mshElementRenderNote(int type);

}  // namespace lancer
