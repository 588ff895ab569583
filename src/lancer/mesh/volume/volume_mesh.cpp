#include "lancer/mesh/volume/volume_mesh.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace lancer {

const char* cellShapeName(CellShape shape) {
  switch (shape) {
    case CellShape::kTetrahedron:
      return "tetrahedron";
    case CellShape::kHexahedron:
      return "hexahedron";
    case CellShape::kPrism:
      return "prism";
    case CellShape::kPyramid:
      break;
  }
  return "pyramid";
}

const VolumeField* VolumeMesh::findField(const std::string& name, int step) const {
  for (const VolumeField& field : fields)
    if (field.name == name && field.step == step) return &field;
  return nullptr;
}

std::string VolumeMesh::fieldNameList() const {
  std::vector<std::string> names;
  for (const VolumeField& field : fields)
    if (std::find(names.begin(), names.end(), field.name) == names.end()) names.push_back(field.name);
  return names.empty() ? "none" : fmt::format("{}", fmt::join(names, ", "));
}

std::vector<const VolumeField*> VolumeMesh::fieldSteps(const std::string& name) const {
  std::vector<const VolumeField*> steps;
  for (const VolumeField& field : fields)
    if (field.name == name) steps.push_back(&field);
  return steps;
}

VolumeField nodeMeans(const VolumeMesh& volume, const VolumeField& field) {
  if (field.at == FieldAt::kNode) return field;
  VolumeField means = field;
  means.at = FieldAt::kNode;
  const auto components = static_cast<std::size_t>(field.components);
  std::vector<double> sum(volume.nodes.size() * components, 0.0);
  std::vector<std::uint32_t> count(volume.nodes.size(), 0);
  for (std::size_t cell = 0; cell < volume.cells.size(); ++cell) {
    const int corners = cellCornerCount(volume.shapes[cell]);
    for (int k = 0; k < corners; ++k) {
      const float* value =
          field.at == FieldAt::kElement
              ? field.values.data() + cell * components
              : field.values.data() + (cell * kMaxCellCorners + static_cast<std::size_t>(k)) * components;
      if (!std::isfinite(value[0])) continue;
      const std::uint32_t node = volume.cells[cell][static_cast<std::size_t>(k)];
      for (std::size_t c = 0; c < components; ++c) sum[node * components + c] += value[c];
      ++count[node];
    }
  }
  means.values.assign(volume.nodes.size() * components, std::numeric_limits<float>::quiet_NaN());
  for (std::size_t node = 0; node < volume.nodes.size(); ++node)
    if (count[node] > 0)
      for (std::size_t c = 0; c < components; ++c)
        means.values[node * components + c] = static_cast<float>(sum[node * components + c] / count[node]);
  return means;
}

std::vector<std::pair<double, const VolumeField*>> volumeFieldTimeline(const VolumeMesh& volume,
                                                                       const std::string& name) {
  std::vector<const VolumeField*> steps = volume.fieldSteps(name);
  std::sort(steps.begin(), steps.end(),
            [](const VolumeField* a, const VolumeField* b) { return a->step < b->step; });
  bool timed = true;
  for (std::size_t i = 1; i < steps.size(); ++i)
    if (!(steps[i]->time > steps[i - 1]->time)) timed = false;
  std::vector<std::pair<double, const VolumeField*>> timeline;
  timeline.reserve(steps.size());
  for (const VolumeField* step : steps) timeline.emplace_back(timed ? step->time : step->step, step);
  return timeline;
}

VolumeField volumeFieldAt(const VolumeMesh& volume, const std::string& name, double time) {
  const std::vector<std::pair<double, const VolumeField*>> timeline = volumeFieldTimeline(volume, name);
  if (timeline.empty()) throw std::invalid_argument("volumeFieldAt: no field " + name);
  std::size_t next = 0;
  while (next < timeline.size() && timeline[next].first < time) ++next;
  if (next == 0) return *timeline.front().second;
  if (next == timeline.size()) return *timeline.back().second;
  const auto& [t0, a] = timeline[next - 1];
  const auto& [t1, b] = timeline[next];
  if (t1 == time) return *b;
  if (a->at != b->at || a->values.size() != b->values.size()) return *a;  // nothing to blend: the step before
  const auto w = static_cast<float>((time - t0) / (t1 - t0));
  VolumeField blended = *a;
  blended.time = time;
  for (std::size_t k = 0; k < blended.values.size(); ++k)
    blended.values[k] = a->values[k] + w * (b->values[k] - a->values[k]);
  return blended;
}

}  // namespace lancer
