#include "lancer/scene/color_by.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "lancer/scene/suggest.hpp"

namespace lancer {
namespace {

// "\"temperature\" (steps 0, 1), \"velocity\" (step 0)": what a file offers, for messages.
std::string describeFields(const Mesh& mesh) {
  std::string text;
  std::vector<std::string> names;
  for (const MeshField& field : mesh.fields) {
    if (std::find(names.begin(), names.end(), field.name) != names.end()) continue;
    names.push_back(field.name);
    std::vector<int> steps;
    for (const MeshField& other : mesh.fields)
      if (other.name == field.name) steps.push_back(other.step);
    text += fmt::format("{}\"{}\" (step{} {})", text.empty() ? "" : ", ", field.name,
                        steps.size() > 1 ? "s" : "", fmt::join(steps, ", "));
  }
  return text;
}

}  // namespace

std::optional<ColorBy> readColorBy(const std::string& file, const TomlTableReader& mesh) {
  const toml::node* node = mesh.find("color_by");
  if (!node) return std::nullopt;
  const auto* table = node->as_table();
  if (!table)
    mesh.fail(*node, fmt::format(
                         "{} must be a table like {{ field = \"temperature\", map = \"viridis\" }}, found {}",
                         mesh.qualified("color_by"), describeValue(*node)));
  const TomlTableReader reader(*table, mesh.qualified("color_by"), file, SceneTable::MeshColorBy);
  ColorBy spec;
  spec.where = reader.location(*node);
  const std::optional<std::string> field = reader.nonEmptyString("field");
  if (!field)
    reader.failMissing("field", "field = \"temperature\" (a $NodeData or $ElementData view's name)");
  spec.field = *field;
  if (auto step = reader.integer("step", 0, 1'000'000'000)) spec.step = static_cast<int>(*step);
  constexpr std::array<std::string_view, 5> kMapNames = {"viridis", "magma", "coolwarm", "grey", "gray"};
  if (auto map = reader.choice("map", kMapNames))
    spec.map = *parseColorMap(kMapNames[static_cast<std::size_t>(*map)]);
  if (const toml::node* range = reader.find("range")) {
    const auto* array = range->as_array();
    const auto number = [&](std::size_t i) -> std::optional<double> {
      const toml::node* item = array->get(i);
      if (!item || !item->is_number()) return std::nullopt;
      const double value = item->value<double>().value_or(NAN);
      return std::isfinite(value) ? std::optional(value) : std::nullopt;
    };
    if (!array || array->size() != 2 || !number(0) || !number(1))
      reader.fail(*range, fmt::format("{} must be two finite numbers [min, max], found {}",
                                      reader.qualified("range"), describeValue(*range)));
    if (!(*number(0) < *number(1)))
      reader.fail(*range, fmt::format("{} must have min < max, found [{}, {}]", reader.qualified("range"),
                                      *number(0), *number(1)));
    spec.range = std::pair{*number(0), *number(1)};
  }
  return spec;
}

FieldColoring resolveColorBy(const ColorBy& spec, const Mesh& mesh) {
  const MeshField* found = nullptr;
  bool nameFound = false;
  for (const MeshField& field : mesh.fields) {
    if (field.name != spec.field) continue;
    nameFound = true;
    if (field.step == spec.step) {
      found = &field;
      break;
    }
  }
  if (!found) {
    for (const auto& [name, warning] : mesh.source.skippedFields)
      if (name == spec.field)
        throw InputError(spec.where, fmt::format("color_by field \"{}\": its section in {} could not be read "
                                                 "and was skipped ({})",
                                                 spec.field, mesh.source.path, warning));
    if (mesh.fields.empty())
      throw InputError(spec.where,
                       fmt::format("color_by field \"{}\": {} has no fields ($NodeData or $ElementData)",
                                   spec.field, mesh.source.path));
    std::vector<std::string> names;
    for (const MeshField& field : mesh.fields) names.push_back(field.name);
    throw InputError(
        spec.where, nameFound
                        ? fmt::format("color_by field \"{}\" has no step {} in {}; it has {}", spec.field,
                                      spec.step, mesh.source.path, describeFields(mesh))
                        : fmt::format("color_by field \"{}\" is not in {}{}; it has {}", spec.field,
                                      mesh.source.path, didYouMean(spec.field, names), describeFields(mesh)));
  }
  FieldColoring coloring;
  coloring.map = spec.map;
  coloring.perFace = found->perElement;
  const auto [low, high] = spec.range ? *spec.range : std::pair<double, double>(found->range());
  coloring.low = low;
  coloring.high = high;
  // A constant field (low == high) shows the middle of the map.
  const double scale = high > low ? 1.0 / (high - low) : 0.0;
  coloring.t.resize(found->itemCount());
  for (std::size_t i = 0; i < coloring.t.size(); ++i) {
    const double value = found->scalar(i);
    coloring.t[i] = std::isnan(value) ? NAN
                    : scale == 0      ? 0.5f
                                      : static_cast<float>(std::clamp((value - low) * scale, 0.0, 1.0));
  }
  return coloring;
}

}  // namespace lancer
