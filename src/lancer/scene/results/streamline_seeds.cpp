#include "lancer/scene/results/streamline_seeds.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lancer {

std::vector<Vec3d> rectangleSeeds(const Vec3d& corner, const Vec3d& u, const Vec3d& v, int count) {
  std::vector<Vec3d> seeds;
  if (count <= 0) return seeds;
  // Cells as near square as the count allows: columns / rows as near |u| / |v| as whole numbers go.
  const double aspect = length(u) / std::max(length(v), 1e-300);
  const int columns = std::clamp(static_cast<int>(std::lround(std::sqrt(count * aspect))), 1, count);
  const int rows = (count + columns - 1) / columns;
  seeds.reserve(static_cast<std::size_t>(count));
  for (int row = 0; row < rows; ++row) {
    const int inRow = row + 1 < rows ? columns : count - (rows - 1) * columns;
    const double t = (row + 0.5) / rows;
    for (int column = 0; column < inRow; ++column)
      seeds.push_back(corner + u * ((column + 0.5) / inRow) + v * t);
  }
  return seeds;
}

namespace {

// The seeds a StreamlineSpec gives (not Automatic) in the volume's frame.
std::vector<Vec3d> givenSeeds(const StreamlineSpec& spec, const VolumeMesh& volume,
                              const InstanceTransform& transform) {
  const auto local = [&](const Vec3d& p) { return transform.toLocal(p) - volume.origin; };
  std::vector<Vec3d> seeds;
  switch (spec.seeds) {
    case StreamlineSpec::Seeds::Automatic:
      return seeds;
    case StreamlineSpec::Seeds::Points:
      for (const Vec3d& p : spec.points) seeds.push_back(local(p));
      return seeds;
    case StreamlineSpec::Seeds::Line: {
      const Vec3d a = local(spec.points[0]), b = local(spec.points[1]);
      for (int i = 0; i < spec.count; ++i)
        seeds.push_back(a + (b - a) * (spec.count == 1 ? 0.5 : static_cast<double>(i) / (spec.count - 1)));
      return seeds;
    }
    case StreamlineSpec::Seeds::Rectangle:
      for (const Vec3d& p :
           rectangleSeeds(spec.rectangleCorner, spec.rectangleEdgeU, spec.rectangleEdgeV, spec.count))
        seeds.push_back(local(p));
      return seeds;
    case StreamlineSpec::Seeds::Disk:
      break;
  }
  // A disk: the points of a sunflower spiral, evenly spread over its area.
  const Vec3d n = normalize(transform.normalToLocal(spec.diskNormal));
  const Vec3d u = normalize(cross(n, std::abs(n.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0})), v = cross(n, u);
  const Vec3d centre = local(spec.diskCenter);
  const double radius = spec.diskRadius * length(transform.normalToLocal(u)) / std::max(length(u), 1e-300);
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  for (int i = 0; i < spec.count; ++i) {
    const double r = radius * std::sqrt((i + 0.5) / spec.count), angle = i * golden;
    seeds.push_back(centre + u * (r * std::cos(angle)) + v * (r * std::sin(angle)));
  }
  return seeds;
}

}  // namespace

std::vector<Vec3d> streamlineSeeds(const StreamlineSpec& spec, const VolumeMesh& volume,
                                   const VolumeLocator& locator, const InstanceTransform& transform,
                                   const PlanarDomain* planar) {
  if (spec.seeds == StreamlineSpec::Seeds::Automatic)
    return planar ? automaticPlanarSeeds(*planar, locator, spec.count)
                  : automaticSeeds(volume, locator, spec.count);
  std::vector<Vec3d> seeds = givenSeeds(spec, volume, transform);
  if (planar)
    for (Vec3d& seed : seeds) seed = ontoPlane(*planar, seed);
  return seeds;
}

}  // namespace lancer
