#include "lancer/scene/results/color_by.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "lancer/mesh/field_steps.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/suggest.hpp"

namespace lancer {
namespace {

// The legend and band keys: title, units, bands, legend.
void readLegendKeys(const TomlTableReader& reader, ColorBy& spec) {
  if (auto title = reader.text("title", kMaxDrawnText)) spec.title = *title;
  if (auto units = reader.text("units", kMaxDrawnText)) spec.units = *units;
  if (auto bands = reader.integer("bands", 1, kMaxBands)) spec.bands = static_cast<int>(*bands);
  if (auto legend = reader.choice("legend", kLegendPlacementNames))
    spec.legend = static_cast<LegendPlacement>(*legend);
}

constexpr std::string_view kListExample = R"(["#000080", "white", "#800000"])";

// The `map` key: a name, or a list of colours (each text or [r, g, b]).
ColorMap readColorMap(const TomlTableReader& reader, const toml::node& node) {
  const std::string key = reader.qualified("map");
  if (node.is_string()) {
    const std::string name = node.value<std::string>().value_or("");
    if (std::optional<ColorMap> map = ColorMap::named(name)) return *map;
    reader.fail(node, fmt::format("{}: {}", key, unknownColorMapMessage(name)));
  }
  const toml::array* array = node.as_array();
  if (!array)
    reader.fail(
        node, fmt::format("{} must be a colour map's name (\"viridis\") or a list of colours ({}), found {}",
                          key, kListExample, describeValue(node)));
  if (array->size() < 2 || array->size() > kMaxListColors)
    reader.fail(node,
                fmt::format("{} must list 2 to {} colours, evenly spaced from the low end to the high end, "
                            "found {}",
                            key, kMaxListColors, describeValue(node)));
  std::vector<Vec3> colors;
  std::string name = "[";
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& item = *array->get(i);
    const std::string itemKey = fmt::format("{}[{}]", key, i);
    if (item.is_string()) {
      const std::string text = item.value<std::string>().value_or("");
      const std::optional<Vec3> color = parseColor(text);
      if (!color) reader.fail(item, fmt::format("{}: {}", itemKey, unknownColorMessage(text)));
      colors.push_back(*color);
      name += fmt::format("{}\"{}\"", i == 0 ? "" : ", ", text);
      continue;
    }
    const toml::array* triple = item.as_array();
    std::array<double, 3> rgb{NAN, NAN, NAN};
    for (std::size_t c = 0; triple && triple->size() == 3 && c < 3; ++c)
      if (const toml::node* channel = triple->get(c); channel->is_number())
        rgb[c] = channel->value<double>().value_or(NAN);
    if (!std::all_of(rgb.begin(), rgb.end(), [](double c) { return c >= 0 && c <= 1; }))
      reader.fail(item, fmt::format("{} must be a colour: \"#rrggbb\", \"#rgb\", a CSS colour name such as "
                                    "\"navy\", or [r, g, b] with each 0 to 1; found {}",
                                    itemKey, describeValue(item)));
    colors.push_back(toFloat(Vec3d{rgb[0], rgb[1], rgb[2]}));
    name += fmt::format("{}[{:g}, {:g}, {:g}]", i == 0 ? "" : ", ", rgb[0], rgb[1], rgb[2]);
  }
  return ColorMap::fromColors(std::move(colors), name + "]");
}

}  // namespace

std::string unknownColorMapMessage(std::string_view name) {
  if (name.starts_with("gmsh:"))
    return fmt::format(
        "\"{}\" is not one of gmsh's colour maps: gmsh:0 to gmsh:24 (gmsh's View.ColormapNumber), "
        "with _r to reverse one",
        name);
  // "virdis_r" is offered "viridis_r".
  const bool reversed = name.size() > 2 && name.ends_with("_r");
  const std::string_view base = reversed ? name.substr(0, name.size() - 2) : name;
  const std::vector<std::string_view> names = colorMapNames();
  const std::optional<std::string> closest = closestName(base, std::span<const std::string_view>(names));
  return fmt::format("\"{}\" is not a colour map{}: use {}; or a list of colours such as {}", name,
                     closest ? fmt::format(" (did you mean '{}{}'?)", *closest, reversed ? "_r" : "") : "",
                     describeColorMaps(), kListExample);
}

std::string unknownColorMessage(std::string_view text) {
  const std::vector<std::string_view> names = colorNames();
  return fmt::format(
      "\"{}\" is not a colour{}: use \"#rrggbb\", \"#rgb\" or a CSS colour name such as \"navy\"", text,
      didYouMean(text, std::span<const std::string_view>(names)));
}

ColorMap colorMapFromText(std::string_view text, const SourceLocation& where) {
  if (text.find(',') == std::string_view::npos) {
    if (std::optional<ColorMap> map = ColorMap::named(text)) return *map;
    throw InputError(where, unknownColorMapMessage(text));
  }
  std::vector<Vec3> colors;
  std::string name = "[";
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    std::string_view item = text.substr(start, comma - start);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
    const std::optional<Vec3> color = parseColor(item);
    if (!color)
      throw InputError(where, fmt::format("colour {}: {}", colors.size() + 1, unknownColorMessage(item)));
    colors.push_back(*color);
    name += fmt::format("{}\"{}\"", colors.size() == 1 ? "" : ", ", item);
    start = comma + 1;
  }
  if (colors.size() > kMaxListColors)
    throw InputError(where, fmt::format("{} colours: give 2 to {}", colors.size(), kMaxListColors));
  return ColorMap::fromColors(std::move(colors), name + "]");
}

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
  if (const toml::node* map = reader.find("map")) spec.map = readColorMap(reader, *map);
  constexpr std::array<std::string_view, 2> kScales = {"linear", "log"};
  if (auto scale = reader.choice("scale", kScales)) spec.scale = static_cast<ColorScale>(*scale);
  if (auto component = readFieldComponent(reader)) spec.component = *component;
  if (const toml::node* range = reader.find("range"); range && range->is_string()) {
    if (range->value<std::string>() != "step")
      reader.fail(*range, fmt::format("{} must be [min, max], \"step\" (each step its own range) or left out "
                                      "(the range over every step), found {}",
                                      reader.qualified("range"), describeValue(*range)));
    spec.perStepRange = true;
  } else if (range) {
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
    if (const std::string problem =
            colorRangeProblem(reader.qualified("range"), *number(0), *number(1), spec.scale);
        !problem.empty())
      reader.fail(*range, problem);
    spec.range = std::pair{*number(0), *number(1)};
  }
  readLegendKeys(reader, spec);
  return spec;
}

std::string fieldTitle(const std::string& name, const FieldComponent& component, int components) {
  if (components == 1) return name;
  switch (component.kind) {
    case FieldComponent::Kind::Magnitude:
      return "|" + name + "|";
    case FieldComponent::Kind::VonMises:
      return name + " (von Mises)";
    case FieldComponent::Kind::Index:
      break;
  }
  static constexpr const char* kAxes[] = {"x", "y", "z"};
  static constexpr const char* kTensor[] = {"xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"};
  const int i = component.index;
  if (components == 3 && i >= 0 && i < 3) return fmt::format("{} ({})", name, kAxes[i]);
  if (components == 9 && i >= 0 && i < 9) return fmt::format("{} ({})", name, kTensor[i]);
  return fmt::format("{} (component {})", name, i);
}

std::string colorRangeProblem(std::string_view name, double low, double high, ColorScale scale) {
  if (!std::isfinite(low) || !std::isfinite(high))
    return fmt::format("{} must be two finite numbers, found {} and {}", name, low, high);
  if (!(low < high)) return fmt::format("{} must have min < max, found [{}, {}]", name, low, high);
  if (scale == ColorScale::Log && !(low > 0))
    return fmt::format(
        "{} must have min > 0 with scale = \"log\", found [{}, {}]: the low end is "
        "where the map starts (values below it, 0 and negative ones included, "
        "are drawn at it), e.g. [{:.3g}, {}]",
        name, low, high, high * 1e-3, high);
  return {};
}

const MeshField& findMeshField(std::string_view key, const std::string& name, int step, const Mesh& mesh,
                               const SourceLocation& where) {
  const MeshField* found = nullptr;
  bool nameFound = false;
  for (const MeshField& field : mesh.fields) {
    if (field.name != name) continue;
    nameFound = true;
    if (field.step == step) {
      found = &field;
      break;
    }
  }
  if (found) return *found;
  for (const auto& [skipped, warning] : mesh.source.skippedFields)
    if (skipped == name)
      throw InputError(
          where, fmt::format("{} field \"{}\": its section in {} could not be read and was skipped ({})", key,
                             name, mesh.source.path, warning));
  if (mesh.fields.empty())
    throw InputError(where, fmt::format("{} field \"{}\": {} has no fields ($NodeData or $ElementData)", key,
                                        name, mesh.source.path));
  const std::vector<std::string> names = viewNames(mesh);
  throw InputError(where, nameFound
                              ? fmt::format("{} field \"{}\" has no step {} in {}; it has {}", key, name,
                                            step, mesh.source.path, describeViews(mesh))
                              : fmt::format("{} field \"{}\" is not in {}{}; it has {}", key, name,
                                            mesh.source.path, didYouMean(name, names), describeViews(mesh)));
}

std::optional<FieldComponent> readFieldComponent(const TomlTableReader& reader) {
  const toml::node* component = reader.find("component");
  if (!component) return std::nullopt;
  const std::string text = component->is_integer()
                               ? std::to_string(component->value<std::int64_t>().value_or(-1))
                               : component->value<std::string>().value_or("");
  const std::optional<FieldComponent> parsed = parseFieldComponent(text);
  if (!parsed)
    reader.fail(*component, fmt::format("{} must be \"magnitude\", \"x\", \"y\", \"z\", \"von_mises\" or an "
                                        "index 0 to 8, found {}",
                                        reader.qualified("component"), describeValue(*component)));
  return parsed;
}

MeshField meshFieldAt(std::string_view key, const std::string& name, std::optional<int> step,
                      const Mesh& mesh, const StepSelection& when, const SourceLocation& where) {
  const std::vector<const MeshField*> steps = viewSteps(mesh, name);
  if (step || steps.empty()) return loadedField(findMeshField(key, name, step.value_or(0), mesh, where));
  std::string problem;
  std::optional<MeshField> found = viewAt(steps, when, problem);
  if (!found)
    throw InputError(
        where, fmt::format("{} field \"{}\" {} in {}{}; it has {}", key, name, problem, mesh.source.path,
                           when.where.empty() ? "" : fmt::format(" ({})", when.where), describeViews(mesh)));
  return std::move(*found);
}

LogScaleWords logScaleWords(const ColorBy& spec, double high) {
  const bool option = !spec.logOption.empty();
  const bool cli = spec.logOption.starts_with("--");
  LogScaleWords words;
  words.where = option ? SourceLocation{spec.logOption} : spec.where;
  words.log = option ? spec.logOption : "scale = \"log\"";
  words.advice = !option ? fmt::format("range = [{:.3g}, {:.3g}]", high * 1e-3, high)
                 : cli   ? fmt::format("--range {:.3g}:{:.3g}", high * 1e-3, high)
                         : fmt::format("range=({:.3g}, {:.3g})", high * 1e-3, high);
  words.linear = !option ? "scale = \"linear\"" : fmt::format("leave {} out", spec.logOption);
  return words;
}

FieldColoring resolveColorBy(const ColorBy& spec, const Mesh& mesh, const StepSelection& scene) {
  const std::vector<const MeshField*> steps = viewSteps(mesh, spec.field);
  if (steps.empty()) {
    for (const auto& [name, warning] : mesh.source.skippedFields)
      if (name == spec.field)
        throw InputError(spec.where, fmt::format("color_by field \"{}\": its section in {} could not be read "
                                                 "and was skipped ({})",
                                                 spec.field, mesh.source.path, warning));
    if (mesh.fields.empty())
      throw InputError(spec.where,
                       fmt::format("color_by field \"{}\": {} has no fields ($NodeData or $ElementData)",
                                   spec.field, mesh.source.path));
    throw InputError(spec.where, fmt::format("color_by field \"{}\" is not in {}{}; it has {}", spec.field,
                                             mesh.source.path, didYouMean(spec.field, viewNames(mesh)),
                                             describeViews(mesh)));
  }
  if (const std::string problem = componentProblem(spec.component, steps.front()->components);
      !problem.empty())
    throw InputError(spec.where,
                     fmt::format("color_by field \"{}\" in {}: {}", spec.field, mesh.source.path, problem));
  StepSelection when = scene;
  if (spec.step) when = StepSelection{spec.step, std::nullopt, "color_by.step"};
  std::string problem;
  const std::optional<ViewValues> found = viewValuesAt(steps, when, problem);  // not copied
  if (!found) {
    const bool fromScene = !spec.step && !scene.where.empty();
    const std::string message =
        fmt::format("color_by field \"{}\" {} in {}{}; it has {}", spec.field, problem, mesh.source.path,
                    fromScene ? fmt::format(" ({})", scene.where) : "", describeViews(mesh));
    throw InputError(spec.where, message);
  }
  FieldColoring coloring;
  coloring.map = spec.map;
  coloring.at = found->field->at;
  coloring.components = found->field->components;
  std::pair<double, double> range;
  if (spec.range) {
    range = *spec.range;
  } else if (spec.perStepRange) {  // a blend's own range needs its values
    range = found->b ? componentRange(*viewAt(steps, when, problem), spec.component)
                     : componentRange(*found->field, spec.component);
  } else {  // every step's: a colour means the same value whichever step is shown
    range = {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (const MeshField* step : steps) {
      const auto [low, high] = componentRange(*step, spec.component);
      range = {std::min(range.first, low), std::max(range.second, high)};
    }
  }
  if (!(range.first <= range.second)) range = {0, 0};
  const auto [low, high] = range;
  if (spec.scale == ColorScale::Log && !(low > 0)) {
    const std::string over = spec.perStepRange || spec.step ? "at the step shown" : "over every step";
    const bool option = !spec.logOption.empty();
    const auto [where, log, advice, linear] = logScaleWords(spec, high);
    throw InputError(
        where,
        high > 0
            ? fmt::format("color_by field \"{}\" in {} has values down to {:g} ({}), but {} needs "
                          "values > 0: give a range whose low end is > 0, e.g. {} (values below it are "
                          "drawn at it), or {}",
                          spec.field, mesh.source.path, low + 0.0, over, log, advice, linear)
            : fmt::format("color_by field \"{}\" in {} has no value above 0 (its greatest is {:g}, {}), so "
                          "{} cannot show it: {}",
                          spec.field, mesh.source.path, high + 0.0, over, log,
                          option ? linear : "use " + linear));  // + 0.0: -0 said as 0
  }
  coloring.low = low;
  coloring.high = high;
  coloring.scale = spec.scale;
  const MapPosition position(low, high);
  const int components = found->field->components;
  coloring.t.resize(found->size() / static_cast<std::size_t>(components));
  std::vector<float> blended(static_cast<std::size_t>(components));  // one item of a blend
  for (std::size_t i = 0; i < coloring.t.size(); ++i) {
    const std::size_t first = i * static_cast<std::size_t>(components);
    const float* item = found->a->data() + first;
    if (found->b) {
      for (int c = 0; c < components; ++c)
        blended[static_cast<std::size_t>(c)] = (*found)[first + static_cast<std::size_t>(c)];
      item = blended.data();
    }
    const double scalar = componentScalar(item, components, spec.component);
    coloring.t[i] = spec.scale == ColorScale::Log ? static_cast<float>(scalar) : position(scalar);
  }
  return coloring;
}

}  // namespace lancer
