#include "lancer/scene/isolines.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "lancer/scene/color_by.hpp"

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
  if (!field) reader.failMissing("field", "field = \"temperature\" (a $NodeData view's name)");
  spec.field = *field;
  if (auto step = reader.integer("step", 0, 1'000'000'000)) spec.step = static_cast<int>(*step);
  if (auto count = reader.integer("count", 1, 1000)) spec.count = static_cast<int>(*count);
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
  if (auto color = reader.vector("color", Triple::Rgb, NumberRange::between(0, 1)))
    spec.color = toFloat(*color);
  if (auto width = reader.number("width", NumberRange::between(0.1, 100))) spec.widthPixels = float(*width);
  return spec;
}

std::vector<double> evenIsoValues(double low, double high, int count) {
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(std::max(count, 0)));
  for (int i = 0; i < count; ++i) values.push_back(low + (high - low) * (i + 0.5) / count);
  return values;
}

ResolvedIsolines resolveIsolines(const IsolineSpec& spec, const Mesh& mesh) {
  const MeshField& field = findMeshField("isolines", spec.field, spec.step, mesh, spec.where);
  if (field.perElement)
    throw InputError(
        spec.where, fmt::format("isolines field \"{}\" is element data ($ElementData: one value per element, "
                                "constant over each face), so it has no curves to draw; show its steps as "
                                "colours with color_by = {{ field = \"{}\", bands = 8 }} instead",
                                spec.field, spec.field));
  ResolvedIsolines resolved;
  resolved.vertexValue.resize(field.itemCount());
  for (std::size_t i = 0; i < resolved.vertexValue.size(); ++i)
    resolved.vertexValue[i] = static_cast<float>(field.scalar(i));
  std::vector<double> values = spec.values;
  if (values.empty()) {
    const auto [low, high] = field.range();
    values = evenIsoValues(low, high, low < high ? spec.count : 1);
  }
  for (const double v : values) resolved.values.push_back(static_cast<float>(v));
  std::sort(resolved.values.begin(), resolved.values.end());
  resolved.values.erase(std::unique(resolved.values.begin(), resolved.values.end()), resolved.values.end());
  return resolved;
}

}  // namespace lancer
