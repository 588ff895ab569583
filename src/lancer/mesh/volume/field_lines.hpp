// Field lines (streamlines) of a vector field through a volume: from each seed, both ways along the
// field's direction, integrated by the Dormand-Prince 5(4) Runge-Kutta pair with an adaptive step,
// the field taken where the volume locator finds each point (its tetrahedron's linear
// interpolation). A line stops at the volume's boundary, where the field vanishes, at its length or
// step limit.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lancer/mesh/volume/volume_locator.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"

namespace lancer {

struct FieldLineSettings {
  double maxLength = 0;  // each way, in model units; 0: four times the volume's diagonal
  int maxSteps = 2000;   // each way
  // Largest error a step may make, in model units; 0: a thousandth of the mean cell size.
  double tolerance = 0;
  // The cells' size, which scales the steps; 0: the side of a cube of the bounding box's volume
  // over the cell count (a planar domain gives its own: its box says nothing of its cells).
  double cellSize = 0;
  bool forward = true;   // along the field
  bool backward = true;  // against it
  int threads = 0;       // seeds are traced in parallel (0: every core); the lines do not depend on it
};

// Why a line ended, each way.
enum class FieldLineEnd : std::uint8_t { kBoundary, kZeroField, kLength, kSteps, kNotTraced };

struct FieldLine {
  std::vector<Vec3d> points;     // the volume's frame, from the backward end through the seed forward
  std::vector<CellPoint> where;  // each point's cell and weights, to interpolate any field there
  FieldLineEnd backwardEnd = FieldLineEnd::kNotTraced;
  FieldLineEnd forwardEnd = FieldLineEnd::kNotTraced;
  std::size_t seedIndex = 0;  // of the seed in points
};

// One line per seed (the volume's frame); a seed outside the volume gives a line of no points.
std::vector<FieldLine> traceFieldLines(const VolumeMesh& volume, const VolumeLocator& locator,
                                       const VolumeField& field, std::span<const Vec3d> seeds,
                                       const FieldLineSettings& settings);

// `count` seeds spread evenly through the volume: the points of a Halton sequence in its bounding
// box that fall inside an element, in sequence order (the same seeds every time).
std::vector<Vec3d> automaticSeeds(const VolumeMesh& volume, const VolumeLocator& locator, int count);

}  // namespace lancer
