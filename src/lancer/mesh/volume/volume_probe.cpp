#include "lancer/mesh/volume/volume_probe.hpp"

#include <fmt/format.h>

#include "lancer/util/input_error.hpp"

namespace lancer {

ProbeResult probeVolume(const VolumeMesh& volume, const VolumeLocator& locator, const Vec3d& point,
                        const std::string& field, std::optional<int> step, const std::string& file) {
  const SourceLocation where{file};
  if (volume.empty())
    throw InputError(where,
                     "the file has no volume elements (tetrahedra, hexahedra, prisms, pyramids) to "
                     "probe inside; probe reads 3D results");
  if (!field.empty() && volume.fieldSteps(field).empty())
    throw InputError(where,
                     fmt::format("no field '{}' in the file; its fields: {}", field, volume.fieldNameList()));
  if (volume.fields.empty())
    throw InputError(where, "the file has no fields ($NodeData, $ElementData or $ElementNodeData) to probe");
  const Vec3d local = point - volume.origin;
  const CellPoint at = locator.locate(local);
  if (!at.inside()) {
    const Aabbd& box = locator.bounds();
    const Vec3d low = box.lower + volume.origin, high = box.upper + volume.origin;
    throw InputError(where,
                     fmt::format("the point ({}, {}, {}) is inside no volume element (the volume spans "
                                 "({}, {}, {}) to ({}, {}, {})); give a point inside the mesh",
                                 point.x, point.y, point.z, low.x, low.y, low.z, high.x, high.y, high.z));
  }
  ProbeResult result;
  result.cell = at.cell;
  result.shape = volume.shapes[at.cell];
  for (const VolumeField& candidate : volume.fields) {
    if (!field.empty() && candidate.name != field) continue;
    if (step && candidate.step != *step) continue;
    ProbeValue value;
    value.name = candidate.name;
    value.at = candidate.at;
    value.step = candidate.step;
    value.time = candidate.time;
    value.values.resize(static_cast<std::size_t>(candidate.components));
    locator.interpolate(candidate, at, value.values.data());
    result.values.push_back(std::move(value));
  }
  if (result.values.empty()) {
    std::vector<int> steps;
    for (const VolumeField& candidate : volume.fields)
      if (field.empty() || candidate.name == field) steps.push_back(candidate.step);
    std::sort(steps.begin(), steps.end());
    steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
    throw InputError(where,
                     fmt::format("no step {} of {}; its steps: {}", step.value_or(0),
                                 field.empty() ? "any field" : "'" + field + "'", fmt::join(steps, ", ")));
  }
  return result;
}

}  // namespace lancer
