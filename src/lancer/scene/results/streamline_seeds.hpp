// Where field lines start: the seeds a `streamlines` table gives (a line, points, a disk, a
// rectangle) or the automatic ones, in the frame of the volume they are traced through.
#pragma once

#include <vector>

#include "lancer/mesh/volume/planar_domain.hpp"
#include "lancer/mesh/volume/volume_locator.hpp"
#include "lancer/scene/instance_transform.hpp"
#include "lancer/scene/results/volume_view_spec.hpp"

namespace lancer {

// `count` seeds on the rectangle (a parallelogram when the edges are not square) corner + s u + t v,
// 0 <= s, t <= 1: a grid of columns along u and rows along v with cells as near square as the count
// allows (round(sqrt(count |u| / |v|)) columns, clamped to 1 .. count, and as many rows as they
// need), each seed at its cell's centre, row by row from the corner; the last row holds the seeds
// left over, spread evenly across it at the centres of its own equal cells.
std::vector<Vec3d> rectangleSeeds(const Vec3d& corner, const Vec3d& u, const Vec3d& v, int count);

// The seeds of `spec` (scene coordinates, placed by the mesh's `transform`) in the volume's frame;
// the automatic ones spread through the volume, or across `planar` when given (then every seed is
// moved onto its plane).
std::vector<Vec3d> streamlineSeeds(const StreamlineSpec& spec, const VolumeMesh& volume,
                                   const VolumeLocator& locator, const InstanceTransform& transform,
                                   const PlanarDomain* planar);

}  // namespace lancer
