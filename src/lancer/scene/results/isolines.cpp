#include "lancer/scene/results/isolines.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lancer/scene/face_elements.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/results/color_by.hpp"

namespace lancer {

std::optional<IsolineSpec> readIsolines(const std::string& file, const TomlTableReader& mesh) {
  const toml::node* node = mesh.find("isolines");
  if (!node) return std::nullopt;
  const auto* table = node->as_table();
  if (!table)
    mesh.fail(*node,
              fmt::format("{} must be a table like {{ field = \"temperature\", count = 10 }}, found {}",
                          mesh.qualified("isolines"), describeValue(*node)));
  const TomlTableReader reader(*table, mesh.qualified("isolines"), file, SceneTable::MeshIsolines);
  IsolineSpec spec;
  spec.where = reader.location(*node);
  const std::optional<std::string> field = reader.nonEmptyString("field");
  if (!field) reader.failMissing("field", "field = \"temperature\" (a view's name)");
  spec.field = *field;
  if (auto step = reader.integer("step", 0, 1'000'000'000)) spec.step = static_cast<int>(*step);
  if (auto component = readFieldComponent(reader)) spec.component = *component;
  if (auto count = reader.integer("count", 1, kMaxIsolineCount)) spec.count = static_cast<int>(*count);
  if (const toml::node* values = reader.find("values")) {
    const auto* array = values->as_array();
    if (!array || array->empty() || array->size() > 1000)
      reader.fail(*values, fmt::format("{} must be an array of 1 to 1000 numbers, found {}",
                                       reader.qualified("values"), describeValue(*values)));
    for (const toml::node& item : *array) {
      const double value = item.is_number() ? item.value<double>().value_or(NAN) : NAN;
      if (!std::isfinite(value))
        reader.fail(item, fmt::format("{} must hold finite numbers, found {}", reader.qualified("values"),
                                      describeValue(item)));
      spec.values.push_back(value);
    }
    if (reader.find("count"))
      reader.fail(*values, fmt::format("{} gives both count and values: keep one", reader.label()));
  }
  if (const toml::node* color = reader.find("color"); color && color->is_string()) {
    if (color->value<std::string>() != "map")
      reader.fail(*color, fmt::format("{} must be [r, g, b] or \"map\" (each line in its value's colour), "
                                      "found {}",
                                      reader.qualified("color"), describeValue(*color)));
    spec.colorFromMap = true;
  } else if (auto rgb = reader.vector("color", Triple::Rgb, NumberRange::between(0, 1))) {
    spec.color = toFloat(*rgb);
  }
  if (auto width = reader.number("width", NumberRange::between(0.1, 100))) spec.widthPixels = float(*width);
  return spec;
}

std::vector<float> elementMeansAtVertices(const Mesh& mesh, const std::vector<float>& faceValues) {
  const FaceElements elements = faceElements(mesh);
  std::vector<double> sum(mesh.positions.size(), 0.0);
  std::vector<std::uint32_t> count(mesh.positions.size(), 0);
  const auto add = [&](std::uint32_t vertex, std::uint32_t face) {
    const float value = faceValues[face];
    if (std::isnan(value)) return;
    sum[vertex] += value;
    ++count[vertex];
  };
  if (elements.count() == mesh.faces.size()) {  // one face per element: each meets a vertex once
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f)
      for (int c = 0; c < mesh.faces[f].cornerCount(); ++c) add(mesh.faces[f].vertex[c], f);
  } else {  // split second-order elements: each element once at each of its vertices
    std::vector<std::pair<std::uint32_t, std::uint32_t>> vertexElement;
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f)
      for (int c = 0; c < mesh.faces[f].cornerCount(); ++c)
        vertexElement.emplace_back(mesh.faces[f].vertex[c], elements.ofFace[f]);
    std::sort(vertexElement.begin(), vertexElement.end());
    vertexElement.erase(std::unique(vertexElement.begin(), vertexElement.end()), vertexElement.end());
    for (const auto& [vertex, element] : vertexElement) add(vertex, elements.first[element]);
  }
  std::vector<float> means(mesh.positions.size(), std::numeric_limits<float>::quiet_NaN());
  for (std::size_t v = 0; v < means.size(); ++v)
    if (count[v]) means[v] = static_cast<float>(sum[v] / count[v]);
  return means;
}

std::vector<double> evenIsoValues(double low, double high, int count) {
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(std::max(count, 0)));
  for (int i = 0; i < count; ++i) values.push_back(low + (high - low) * (i + 0.5) / count);
  return values;
}

std::vector<double> logIsoValues(double low, double high, int count) {
  std::vector<double> values = evenIsoValues(std::log(low), std::log(high), count);
  for (double& v : values) v = std::exp(v);
  return values;
}

std::vector<double> gmshIsoValues(double low, double high, int count) {
  if (count == 1) return {0.5 * (low + high)};
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(std::max(count, 0)));
  for (int i = 0; i < count; ++i)
    values.push_back(i == 0 ? low : i == count - 1 ? high : low + (high - low) * i / (count - 1));
  return values;
}

ResolvedIsolines resolveIsolines(const IsolineSpec& spec, const Mesh& mesh, const StepSelection& when,
                                 std::optional<std::pair<double, double>> colorRange, ColorScale colorScale) {
  const MeshField field = meshFieldAt("isolines", spec.field, spec.step, mesh, when, spec.where);
  if (const std::string problem = componentProblem(spec.component, field.components); !problem.empty())
    throw InputError(spec.where,
                     fmt::format("isolines field \"{}\" in {}: {}", spec.field, mesh.source.path, problem));
  ResolvedIsolines resolved;
  resolved.at = field.at;
  resolved.vertexValue.resize(field.itemCount());
  const auto components = static_cast<std::size_t>(field.components);
  for (std::size_t i = 0; i < resolved.vertexValue.size(); ++i)
    resolved.vertexValue[i] =
        componentScalar(field.values.data() + i * components, field.components, spec.component);
  if (field.at == FieldAt::kElement) {
    // Constant over each element, the field has no curves of its own: they are drawn on its mean at
    // each vertex, as ParaView's Cell Data to Point Data before Contour.
    resolved.vertexValue = elementMeansAtVertices(mesh, resolved.vertexValue);
    resolved.at = FieldAt::kNode;
    resolved.fromElementData = true;
  }
  std::vector<double> values = spec.values;
  const bool log = colorRange && colorScale == ColorScale::Log && colorRange->first > 0 &&
                   colorRange->second > colorRange->first;
  if (values.empty() && log) {  // the colours' log scale: lines evenly spaced in log(value)
    const auto [low, high] = *colorRange;
    if (spec.colorRangeEnds) {  // gmsh's: 10^(log low + i (log high - log low) / (count - 1))
      values = gmshIsoValues(std::log(low), std::log(high), spec.count);
      for (double& v : values) v = std::exp(v);
      if (spec.count > 1) {  // the ends exactly, as gmsh keeps them
        values.front() = low;
        values.back() = high;
      }
    } else {
      values = logIsoValues(low, high, spec.count);
    }
  } else if (values.empty() && spec.colorRangeEnds && colorRange) {
    values = gmshIsoValues(colorRange->first, colorRange->second, spec.count);
  } else if (values.empty()) {
    // The range of the step shown when pinned, else of every step: a line means one value throughout.
    std::pair<double, double> range = componentRange(field, spec.component);
    if (!spec.step)
      for (const MeshField* step : viewSteps(mesh, spec.field)) {
        const auto [low, high] = componentRange(*step, spec.component);
        range = {std::min(range.first, low), std::max(range.second, high)};
      }
    const auto [low, high] = range;
    if (low <= high) values = evenIsoValues(low, high, low < high ? spec.count : 1);
  }
  for (const double v : values) resolved.values.push_back(static_cast<float>(v));
  std::sort(resolved.values.begin(), resolved.values.end());
  resolved.values.erase(std::unique(resolved.values.begin(), resolved.values.end()), resolved.values.end());
  return resolved;
}

}  // namespace lancer
