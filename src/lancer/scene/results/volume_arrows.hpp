// Arrows through a volume: `arrows = { field = "e", grid = [nx, ny, nz] }` puts one at the centre of
// each cell of a regular grid over the volume's bounds, its vector interpolated in the volume element
// that holds it (mesh/volume/volume_locator.hpp); points in no element draw none.
#pragma once

#include <string>
#include <utility>

#include "lancer/mesh/field_steps.hpp"
#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"
#include "lancer/scene/results/arrow_spec.hpp"

namespace lancer {

// The grid's points, in the volume's frame (relative to its origin), x fastest: point (i, j, k) at
// lower + (i + 1/2, j + 1/2, k + 1/2) * spacing, spacing the bounds' extent over the grid's counts.
struct ArrowGrid {
  std::vector<Vec3d> points;
  double cellSize = 0;  // the least spacing along an axis the volume spans: an arrow's room
};
ArrowGrid arrowGrid(const Aabbd& bounds, const std::array<int, 3>& counts);

// The arrows of spec (spec.grid set) through `volume` at the step spec pins, else the scene's step,
// else its time (steps blended), as arrowsAlong builds them: scaled so that the longest over every
// step the arrows follow is 0.9 grid cells (spec.scale otherwise). InputError at spec.where when the
// volume has no elements or no such field (or step), or the field does not have 3 components
// (`file`: the mesh's, for messages).
Mesh volumeArrowMesh(const ArrowSpec& spec, const VolumeMesh& volume, const StepSelection& when,
                     const std::string& file);

// The least and greatest magnitude of the field over the volume's values (every step, or the pinned
// one): the arrows' colour range; {inf, -inf} when it has none.
std::pair<double, double> volumeMagnitudeRange(const VolumeMesh& volume, const std::string& field,
                                               std::optional<int> step);

}  // namespace lancer
