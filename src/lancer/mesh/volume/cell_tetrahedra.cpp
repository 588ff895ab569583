#include "lancer/mesh/volume/cell_tetrahedra.hpp"

#include <span>

namespace lancer {
namespace {

using Face = std::array<std::int8_t, 4>;  // corners; -1 after a triangle's third

constexpr Face kHexFaces[] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                              {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
constexpr Face kPrismFaces[] = {{0, 2, 1, -1}, {3, 4, 5, -1}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};

// The two triangles of quad abcd on the diagonal through its corner of least node index.
std::array<std::array<std::uint8_t, 3>, 2> splitQuad(
    const Face& quad, const std::array<std::uint32_t, kMaxCellCorners>& corners) {
  int least = 0;
  for (int i = 1; i < 4; ++i)
    if (corners[static_cast<std::uint8_t>(quad[static_cast<std::size_t>(i)])] <
        corners[static_cast<std::uint8_t>(quad[static_cast<std::size_t>(least)])])
      least = i;
  const auto at = [&](int i) {
    return static_cast<std::uint8_t>(quad[static_cast<std::size_t>((least + i) % 4)]);
  };
  // Rotated so that the diagonal runs from corner 0 to corner 2.
  return {{{at(0), at(1), at(2)}, {at(0), at(2), at(3)}}};
}

void coneFromCentre(std::span<const Face> faces, const std::array<std::uint32_t, kMaxCellCorners>& corners,
                    CellTetrahedra& split) {
  for (const Face& face : faces) {
    if (face[3] < 0) {
      split.tetrahedra[static_cast<std::size_t>(split.count++)] = {
          static_cast<std::uint8_t>(face[0]), static_cast<std::uint8_t>(face[1]),
          static_cast<std::uint8_t>(face[2]), kCellCentre};
      continue;
    }
    for (const auto& triangle : splitQuad(face, corners))
      split.tetrahedra[static_cast<std::size_t>(split.count++)] = {triangle[0], triangle[1], triangle[2],
                                                                   kCellCentre};
  }
}

}  // namespace

CellTetrahedra cellTetrahedra(CellShape shape, const std::array<std::uint32_t, kMaxCellCorners>& corners) {
  CellTetrahedra split;
  switch (shape) {
    case CellShape::kTetrahedron:
      split.count = 1;
      split.tetrahedra[0] = {0, 1, 2, 3};
      break;
    case CellShape::kHexahedron:
      coneFromCentre(kHexFaces, corners, split);
      break;
    case CellShape::kPrism:
      coneFromCentre(kPrismFaces, corners, split);
      break;
    case CellShape::kPyramid:
      for (const auto& triangle : splitQuad(Face{0, 1, 2, 3}, corners))
        split.tetrahedra[static_cast<std::size_t>(split.count++)] = {triangle[0], triangle[1], triangle[2],
                                                                     4};
      break;
  }
  return split;
}

}  // namespace lancer
