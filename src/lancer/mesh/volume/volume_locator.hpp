// Finds the cell that holds a point, and where in it, for probes, field lines and arrows inside a
// volume: a uniform grid over the cells' bounding boxes, then the cell's tetrahedra
// (cell_tetrahedra.hpp) by barycentric coordinates. Values there are the tetrahedron's linear
// interpolation of the corners' (and the centre's) values. From a nearby cell (a hint), a walk
// through neighbouring tetrahedra finds it first.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "lancer/math/aabb.hpp"
#include "lancer/mesh/volume/cell_tetrahedra.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"

namespace lancer {

// A point inside a cell: the tetrahedron's points (cell corners or kCellCentre) and their weights.
struct CellPoint {
  std::uint32_t cell = 0xFFFFFFFFu;  // kNoVertex: outside every cell
  std::array<std::uint8_t, 4> points{};
  std::array<double, 4> weights{};
  bool inside() const { return cell != 0xFFFFFFFFu; }
};

class VolumeLocator {
 public:
  explicit VolumeLocator(const VolumeMesh& volume);
  // The cell holding `point` (in the volume's frame, relative to its origin); a cell that holds it
  // within a relative 1e-9 of its size when the point is on a face. `hint`, a cell to try first
  // (the last one of a field line), makes a walk cheap.
  CellPoint locate(const Vec3d& point, std::uint32_t hint = 0xFFFFFFFFu) const;
  // The field's `components` values at a located point. Element data: the cell's value.
  void interpolate(const VolumeField& field, const CellPoint& at, float* out) const;
  const Aabbd& bounds() const { return bounds_; }

 private:
  bool locateInCell(const Vec3d& point, std::uint32_t cell, CellPoint& found) const;
  // From `cell` through neighbouring tetrahedra towards the point (a field line's next point is a
  // cell or two away); false when it leaves the tetrahedra or the mesh (the grid then decides).
  bool walk(const Vec3d& point, std::uint32_t cell, CellPoint& found) const;
  void buildNodeCells();

  const VolumeMesh& volume_;
  Aabbd bounds_;
  std::array<int, 3> dims_{1, 1, 1};
  Vec3d binSize_{1, 1, 1};
  std::vector<std::uint32_t> binStart_;  // CSR: the cells overlapping each bin
  std::vector<std::uint32_t> binCells_;
  std::vector<std::uint32_t> nodeCellStart_;  // CSR: the cells around each node (for the walk)
  std::vector<std::uint32_t> nodeCells_;
};

// A field's values at a cell's tetrahedron points: corner k at out[k * components], the centre (the
// mean of the corners) at out[kCellCentre * components]; element data gives every point the cell's.
void cellPointValues(const VolumeMesh& volume, const VolumeField& field, std::uint32_t cell, float* out);

}  // namespace lancer
