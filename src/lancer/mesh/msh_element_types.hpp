// The gmsh element types (MSH "elm-type" numbers): how many nodes each has and what lancer makes of
// it (faces, a volume's skin, nothing, or "cannot render"). Numbers from gmsh's GmshDefines.h.
#pragma once

#include <cstdint>
#include <string>

namespace lancer {

enum class MshElementRole : std::uint8_t {
  kIgnored,       // points and lines: not surfaces, silently skipped (still counted as read)
  kSurface,       // triangles and quads up to second order: become faces
  kVolume,        // tetrahedra, hexahedra, prisms, pyramids up to second order: become their skin
  kUnrenderable,  // third order and up, polygons, one-node "elements": counted and reported
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

// "3-node triangle", "10-node tetrahedron", ... for `lancer info`; "type N" for rare ones.
std::string mshElementTypeName(int type);

}  // namespace lancer
