// Scene.quick_look's result keywords (color_by=, isolines=, arrows=, legend=) read as a scene file's
// [[mesh]] keys: each Python value becomes the TOML value the file would hold and goes through the
// scene loader's own readers, so a bad value is refused with the message the file would get.
#include <fmt/format.h>

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <variant>

#include "bindings.hpp"
#include "lancer/scene/arrows.hpp"
#include "lancer/scene/color_by.hpp"
#include "lancer/scene/isolines.hpp"
#include "lancer/scene/render_limits.hpp"

namespace lancer::python {
namespace {

// Where the quick look's keywords are said to be, in messages: "quick_look: error: isolines.count ...".
constexpr const char* kWhere = "quick_look";

// The TOML value a Python value stands for: str, bool, int, float, a list or tuple of them, a dict
// with str keys. `name` is the keyword, for the TypeError.
using TomlValue = std::variant<bool, std::int64_t, double, std::string, toml::array, toml::table>;

TomlValue tomlValue(const py::handle& value, const std::string& name) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) return value.cast<std::int64_t>();
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    toml::array array;
    for (const py::handle item : value)
      std::visit([&](auto&& v) { array.push_back(std::move(v)); }, tomlValue(item, name));
    return array;
  }
  if (py::isinstance<py::dict>(value)) {
    toml::table table;
    for (const auto& [key, item] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(key))
        throw py::type_error(
            fmt::format("{}=: the dict's keys are the scene file's key names (str), found {}", name,
                        py::repr(key).cast<std::string>()));
      const std::string text = key.cast<std::string>();
      std::visit([&](auto&& v) { table.insert_or_assign(text, std::move(v)); }, tomlValue(item, name));
    }
    return table;
  }
  throw py::type_error(fmt::format("{}=: {} is not a str, number, bool, list or dict", name,
                                   py::repr(value).cast<std::string>()));
}

// A keyword's value as the table of its scene key: a field's name stands for { field = name }.
toml::table keyTable(const py::object& value, const std::string& name, std::string_view example) {
  if (py::isinstance<py::str>(value)) {
    toml::table table;
    table.insert("field", value.cast<std::string>());
    return table;
  }
  if (!py::isinstance<py::dict>(value))
    throw py::type_error(
        fmt::format("{}= takes a field's name or a dict of the scene file's keys, e.g. {}", name, example));
  return std::get<toml::table>(tomlValue(value, name));
}

}  // namespace

void applyResultKeywords(MeshInstance& instance, const ResultKeywords& keywords) {
  toml::table mesh;
  if (keywords.colorBy && py::isinstance<py::dict>(*keywords.colorBy))
    mesh.insert("color_by", keyTable(*keywords.colorBy, "color_by", "{'field': 'stress', 'units': 'MPa'}"));
  if (keywords.isolines && !keywords.isolines->is_none())
    mesh.insert("isolines", keyTable(*keywords.isolines, "isolines", "{'field': 'T', 'count': 10}"));
  if (keywords.arrows && !keywords.arrows->is_none())
    mesh.insert("arrows", keyTable(*keywords.arrows, "arrows", "{'field': 'velocity', 'max_count': 300}"));
  const TomlTableReader reader(mesh, "", kWhere, SceneTable::Mesh);
  if (auto colorBy = readColorBy(kWhere, reader)) instance.colorBy = std::move(colorBy);
  if (auto isolines = readIsolines(kWhere, reader)) instance.isolines = std::move(isolines);
  if (auto arrows = readArrows(kWhere, reader)) instance.arrows = std::move(arrows);
  if (keywords.legend) {
    const auto* found =
        std::find(kLegendPlacementNames.begin(), kLegendPlacementNames.end(), *keywords.legend);
    if (found == kLegendPlacementNames.end())
      throw py::value_error(fmt::format("legend='{}': use 'right', 'bottom' or 'none'", *keywords.legend));
    if (!instance.colorBy)
      throw py::value_error(
          fmt::format("legend='{}' shows the colours' legend: give color_by= too", *keywords.legend));
    instance.colorBy->legend = static_cast<LegendPlacement>(found - kLegendPlacementNames.begin());
  }
}

}  // namespace lancer::python
