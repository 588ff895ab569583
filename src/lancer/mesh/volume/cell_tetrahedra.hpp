// Every volume cell as tetrahedra, split the same way on both sides of every shared face, so that
// what is interpolated on the tetrahedra (a slice's colours, an isosurface, a field line) is
// continuous from cell to cell: no cracks.
//
// A quadrilateral face is split along the diagonal through its corner of least node index, which
// both cells sharing it see alike. A pyramid is its two tetrahedra on that split base; a hexahedron
// and a prism are cones from their centre over their faces' triangles (12 and 8 tetrahedra), the
// centre's value being the mean of the corners'. A tetrahedron is itself. So a field given at the
// corners is interpolated piecewise linearly: exactly on tetrahedra, and within each hexahedron,
// prism and pyramid agreeing with the corners and with every face's neighbour.
#pragma once

#include <array>
#include <cstdint>

#include "lancer/mesh/volume/volume_mesh.hpp"

namespace lancer {

// A point of a cell's tetrahedra: a corner (0 .. 7, gmsh's corner order) or the centre.
inline constexpr std::uint8_t kCellCentre = kMaxCellCorners;
inline constexpr int kMaxCellTetrahedra = 12;

struct CellTetrahedra {
  int count = 0;
  std::array<std::array<std::uint8_t, 4>, kMaxCellTetrahedra> tetrahedra{};
};

// The split of a cell whose corners are the volume nodes `corners` (their indices decide the
// diagonals).
CellTetrahedra cellTetrahedra(CellShape shape, const std::array<std::uint32_t, kMaxCellCorners>& corners);

}  // namespace lancer
