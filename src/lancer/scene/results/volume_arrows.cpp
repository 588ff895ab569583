#include "lancer/scene/results/volume_arrows.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lancer/mesh/volume/volume_locator.hpp"
#include "lancer/scene/results/arrows.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

// The steps of the field the arrows follow, checked: a vector field the volume carries.
std::vector<const VolumeField*> arrowSteps(const ArrowSpec& spec, const VolumeMesh& volume,
                                           const std::string& file) {
  if (volume.empty())
    throw InputError(spec.where,
                     fmt::format("arrows on a grid stand inside volume elements, and '{}' has none "
                                 "(tetrahedra, hexahedra, prisms, pyramids); leave out grid to draw "
                                 "them on the surface",
                                 file));
  std::vector<const VolumeField*> steps = volume.fieldSteps(spec.field);
  if (steps.empty())
    throw InputError(spec.where,
                     fmt::format("arrows field \"{}\" is not given inside the volume of '{}' (its "
                                 "fields: {})",
                                 spec.field, file, volume.fieldNameList()));
  const VolumeField& first = *steps.front();
  if (first.components != 3)
    throw InputError(
        spec.where,
        fmt::format("arrows field \"{}\" must be a vector of 3 components (node, element or "
                    "element-node data), but it is {} data of {} component{}",
                    spec.field, fieldAtName(first.at), first.components, first.components == 1 ? "" : "s"));
  return steps;
}

// The field at the moment shown: the pinned step, the scene's step, the scene's time (blended), or
// the first step.
VolumeField shownField(const ArrowSpec& spec, const VolumeMesh& volume,
                       const std::vector<const VolumeField*>& steps, const StepSelection& when) {
  if (const std::optional<int> step = spec.step ? spec.step : when.step) {
    for (const VolumeField* field : steps)
      if (field->step == *step) return *field;
    std::vector<int> have;
    have.reserve(steps.size());
    for (const VolumeField* field : steps) have.push_back(field->step);
    throw InputError(
        spec.where,
        fmt::format("arrows field \"{}\" has no step {} inside the volume{}; its steps: {}", spec.field,
                    *step, spec.step || when.where.empty() ? "" : fmt::format(" ({})", when.where),
                    fmt::join(have, ", ")));
  }
  if (when.time) return volumeFieldAt(volume, spec.field, *when.time);
  return *steps.front();
}

}  // namespace

ArrowGrid arrowGrid(const Aabbd& bounds, const std::array<int, 3>& counts) {
  ArrowGrid grid;
  const Vec3d extent = bounds.upper - bounds.lower;
  const Vec3d spacing{extent.x / counts[0], extent.y / counts[1], extent.z / counts[2]};
  grid.cellSize = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis)
    if (spacing[axis] > 0) grid.cellSize = std::min(grid.cellSize, spacing[axis]);
  if (!std::isfinite(grid.cellSize)) grid.cellSize = 0;
  grid.points.reserve(static_cast<std::size_t>(counts[0]) * static_cast<std::size_t>(counts[1]) *
                      static_cast<std::size_t>(counts[2]));
  for (int k = 0; k < counts[2]; ++k)
    for (int j = 0; j < counts[1]; ++j)
      for (int i = 0; i < counts[0]; ++i)
        grid.points.push_back(bounds.lower +
                              Vec3d{(i + 0.5) * spacing.x, (j + 0.5) * spacing.y, (k + 0.5) * spacing.z});
  return grid;
}

Mesh volumeArrowMesh(const ArrowSpec& spec, const VolumeMesh& volume, const StepSelection& when,
                     const std::string& file) {
  const std::vector<const VolumeField*> steps = arrowSteps(spec, volume, file);
  const VolumeField field = shownField(spec, volume, steps, when);
  const VolumeLocator locator(volume);
  const ArrowGrid grid = arrowGrid(locator.bounds(), *spec.grid);
  // Each point is located once; every step is read at the points found.
  std::vector<CellPoint> found;
  ArrowVectors arrows;
  arrows.cellSize = grid.cellSize;
  std::uint32_t hint = 0xFFFFFFFFu;  // the last cell found: the next point is usually in or near it
  for (const Vec3d& point : grid.points) {
    const CellPoint at = locator.locate(point, hint);
    if (!at.inside()) continue;
    hint = at.cell;
    found.push_back(at);
    arrows.bases.push_back(volume.origin + point);
  }
  const auto vectorsOf = [&](const VolumeField& step, std::vector<Vec3d>& out) {
    out.clear();
    float value[3];
    for (const CellPoint& at : found) {
      locator.interpolate(step, at, value);
      out.push_back({value[0], value[1], value[2]});
    }
  };
  vectorsOf(field, arrows.vectors);
  // The longest arrow of every step the arrows follow (a blend of two steps is no longer than
  // both), so that an arrow's length means one magnitude in every frame of an animation.
  std::vector<Vec3d> stepVectors;
  for (const VolumeField* step : spec.step ? std::vector<const VolumeField*>{} : steps) {
    vectorsOf(*step, stepVectors);
    for (const Vec3d& v : stepVectors)
      if (std::isfinite(length(v))) arrows.largest = std::max(arrows.largest, length(v));
  }
  for (const Vec3d& v : arrows.vectors)
    if (std::isfinite(length(v))) arrows.largest = std::max(arrows.largest, length(v));
  return arrowsAlong(spec, arrows, volume.origin, file, field.time);
}

std::pair<double, double> volumeMagnitudeRange(const VolumeMesh& volume, const std::string& field,
                                               std::optional<int> step) {
  std::pair<double, double> range{INFINITY, -INFINITY};
  for (const VolumeField* values : volume.fieldSteps(field)) {
    if (values->components != 3 || (step && values->step != *step)) continue;
    for (std::size_t i = 0; i + 2 < values->values.size(); i += 3) {
      const double magnitude = length(Vec3d{values->values[i], values->values[i + 1], values->values[i + 2]});
      if (!std::isfinite(magnitude)) continue;  // NaN: a corner slot past the element's last
      range = {std::min(range.first, magnitude), std::max(range.second, magnitude)};
    }
  }
  return range;
}

}  // namespace lancer
