// The result keywords: Scene.quick_look's (color_by=, isolines=, arrows=, legend=) read as a scene
// file's [[mesh]] keys: each Python value becomes the TOML value the file would hold and goes through
// the scene loader's own readers, so a bad value is refused with the message the file would get; and
// render's and animate's (color_map=, range=, log=, ...), the command line's --color-map, --range,
// --log, ..., checked where those are.
#include <fmt/format.h>

#include <pybind11/stl.h>

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <variant>

#include "bindings.hpp"
#include "lancer/image/color_map.hpp"
#include "lancer/scene/arrows.hpp"
#include "lancer/scene/clip_text.hpp"
#include "lancer/scene/color_by.hpp"
#include "lancer/scene/isolines.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/render_overrides.hpp"
#include "render_session.hpp"

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

// color_map=: a map's name, or a list of two or more colours, each a str ('#000080', 'white') or an
// (r, g, b) of numbers 0 to 1, as a scene file's `map` takes them.
ColorMap colorMapArgument(const py::object& map) {
  if (py::isinstance<py::str>(map)) {
    const std::string name = map.cast<std::string>();
    if (std::optional<ColorMap> named = ColorMap::named(name)) return *named;
    throw py::value_error(fmt::format("color_map='{}': {}", name, unknownColorMapMessage(name)));
  }
  if (!py::isinstance<py::list>(map) && !py::isinstance<py::tuple>(map))
    throw py::type_error(
        "color_map= takes a map's name ('viridis', 'RdBu_r', 'gmsh:2') or a list of colours, e.g. "
        "['#000080', 'white', '#800000']");
  std::vector<Vec3> colors;
  std::string name = "[";
  for (const py::handle item : map) {
    const std::size_t i = colors.size();
    if (py::isinstance<py::str>(item)) {
      const std::string text = item.cast<std::string>();
      const std::optional<Vec3> color = parseColor(text);
      if (!color)
        throw py::value_error(fmt::format("color_map=[...]: item {}: {}", i, unknownColorMessage(text)));
      colors.push_back(*color);
      name += fmt::format("{}'{}'", i == 0 ? "" : ", ", text);
      continue;
    }
    std::array<double, 3> rgb{NAN, NAN, NAN};
    try {
      rgb = item.cast<std::array<double, 3>>();
    } catch (const py::cast_error&) {
    }
    if (!std::all_of(rgb.begin(), rgb.end(), [](double c) { return c >= 0 && c <= 1; }))
      throw py::value_error(
          fmt::format("color_map=[...]: item {} is {}: give a colour as '#rrggbb', '#rgb', a CSS "
                      "name or (r, g, b) with each 0 to 1",
                      i, py::repr(item).cast<std::string>()));
    colors.push_back(toFloat(Vec3d{rgb[0], rgb[1], rgb[2]}));
    name += fmt::format("{}({:g}, {:g}, {:g})", i == 0 ? "" : ", ", rgb[0], rgb[1], rgb[2]);
  }
  if (colors.size() < 2 || colors.size() > kMaxListColors)
    throw py::value_error(
        fmt::format("color_map= lists {} colours: give 2 to {}", colors.size(), kMaxListColors));
  return ColorMap::fromColors(std::move(colors), name + "]");
}

void applyResultArguments(const RenderArguments& arguments, RenderOverrides& overrides) {
  overrides.optionPrefix = "";  // messages name the keywords: "range must have min < max"
  if (arguments.colorMap && !arguments.colorMap.is_none())
    overrides.colorMap = colorMapArgument(arguments.colorMap);
  if (arguments.scale && *arguments.scale != "linear" && *arguments.scale != "log")
    throw py::value_error(fmt::format("scale='{}': use 'linear' or 'log'", *arguments.scale));
  if (arguments.log && arguments.scale && *arguments.log != (*arguments.scale == "log"))
    throw py::value_error("log and scale disagree: give one of them");
  if (arguments.log) overrides.scale = *arguments.log ? ColorScale::Log : ColorScale::Linear;
  if (arguments.scale) overrides.scale = *arguments.scale == "log" ? ColorScale::Log : ColorScale::Linear;
  overrides.range = arguments.range;
  if (arguments.legend) {
    overrides.legend = enumFromName<LegendPlacement>(kLegendPlacementNames, *arguments.legend);
    if (!overrides.legend)
      throw py::value_error(fmt::format("legend='{}': use 'right', 'bottom' or 'none'", *arguments.legend));
  }
  overrides.isolines = arguments.isolines;
  overrides.bands = arguments.bands;
  if (arguments.arrows) {
    if (arguments.arrows->empty()) throw py::value_error("arrows='': give the name of a vector field");
    overrides.arrows = *arguments.arrows;
  }
  if (arguments.clip && !arguments.clip.is_none()) {
    // One plane as text, or a list of them, as --clip takes them.
    const bool one = py::isinstance<py::str>(arguments.clip);
    if (!one && !py::isinstance<py::list>(arguments.clip) && !py::isinstance<py::tuple>(arguments.clip))
      throw py::type_error("clip= takes a plane as text ('x=0.5', '0,0,0,1,0,0') or a list of them");
    const py::list planes = one ? py::list(py::make_tuple(arguments.clip)) : py::list(arguments.clip);
    for (const py::handle plane : planes) {
      if (!py::isinstance<py::str>(plane))
        throw py::type_error(fmt::format("clip=: {} is not a plane as text ('x=0.5', '0,0,0,1,0,0')",
                                         py::repr(plane).cast<std::string>()));
      overrides.clips.push_back(clipFromText(plane.cast<std::string>(), SourceLocation{"clip"}));
    }
  }
}

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
