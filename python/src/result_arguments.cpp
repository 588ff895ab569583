// The result keywords: Scene.quick_look's (color_by=, isolines=, arrows=, legend=) read as a scene
// file's [[mesh]] keys: each Python value becomes the TOML value the file would hold and goes through
// the scene loader's own readers, so a bad value is refused with the message the file would get; and
// render's and animate's (color_map=, range=, log=, ...), the command line's --color-map, --range,
// --log, ..., checked where those are.
#include <fmt/format.h>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <variant>

#include "bindings.hpp"
#include "lancer/image/color_map.hpp"
#include "lancer/scene/clip_text.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/render_overrides.hpp"
#include "lancer/scene/results/annotation_kinds.hpp"
#include "lancer/scene/results/arrows.hpp"
#include "lancer/scene/results/color_by.hpp"
#include "lancer/scene/results/isolines.hpp"
#include "lancer/scene/results/volume_view_text.hpp"
#include "lancer/scene/results/volume_views.hpp"
#include "render_session.hpp"

namespace lancer::python {
namespace {

// Where the quick look's keywords are said to be, in messages: "quick_look: error: isolines.count ...".
constexpr const char* kWhere = "quick_look";

// The TOML value a Python value stands for: str, bool, int, float, a list or tuple of them, a dict
// with str keys. `name` is the keyword, for the TypeError.
using TomlValue = std::variant<bool, std::int64_t, double, std::string, toml::array, toml::table>;

TomlValue tomlValue(const py::handle& value, const std::string& name) {
  // numpy arrays and scalars (np.float64 is a float, np.int64 is no int): as their Python values.
  if (py::isinstance<py::array>(value) || py::isinstance(value, py::module_::import("numpy").attr("generic")))
    return tomlValue(value.attr("tolist")(), name);
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) return value.cast<std::int64_t>();
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    toml::array array;
    for (const py::handle item : value)
      std::visit([&](auto&& v) { array.push_back(std::forward<decltype(v)>(v)); }, tomlValue(item, name));
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
      std::visit([&](auto&& v) { table.insert_or_assign(text, std::forward<decltype(v)>(v)); },
                 tomlValue(item, name));
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

// A keyword that is one item or a list of them: the items.
py::list itemsOf(const py::object& value, bool one) {
  return one ? py::list(py::make_tuple(value)) : py::list(value);
}

// slices=: one plane or a list of them, each as --slice's text ('z=0.3', 'y', '0,0,0,0,0,1') or a
// dict of a [[mesh.slice]]'s keys ({'point': [0, 0, 0.1], 'normal': [0, 0, 1]}).
void applySlicesArgument(const py::object& slices, RenderOverrides& overrides) {
  const bool one = py::isinstance<py::str>(slices) || py::isinstance<py::dict>(slices);
  if (!one && !py::isinstance<py::list>(slices) && !py::isinstance<py::tuple>(slices))
    throw py::type_error(
        "slices= takes a plane as text ('z=0.3', 'y', '0,0,0,0,0,1'), a dict {'point': [x, y, z], 'normal': "
        "[x, y, z]}, or a list of them");
  const py::list items = itemsOf(slices, one);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const py::handle item = items[i];
    if (py::isinstance<py::str>(item)) {
      overrides.slices.push_back(sliceFromText(item.cast<std::string>(), SourceLocation{"slices"}));
    } else if (py::isinstance<py::dict>(item)) {
      const toml::table table = std::get<toml::table>(tomlValue(item, "slices"));
      const std::string name = one ? "slices" : fmt::format("slices[{}]", i);
      overrides.slices.push_back(readSlice(TomlTableReader(table, name, "slices", SceneTable::MeshSlice)));
    } else {
      throw py::type_error(
          fmt::format("slices=: {} is not a plane as text ('z=0.3', 'y') or a dict {{'point': [x, y, z], "
                      "'normal': [x, y, z]}}",
                      py::repr(item).cast<std::string>()));
    }
  }
}

// isosurfaces= and streamlines=: --isosurfaces's and --streamlines's FIELD[:COUNT], or a dict of the
// scene keys, read by the scene loader's reader (readVolumeViewKeys) as a [[mesh]]'s `key` table.
VolumeViews volumeKeyArgument(const py::object& value, const char* key, int most, std::string_view example) {
  VolumeViews views;
  if (py::isinstance<py::str>(value)) {
    const auto [field, count] = fieldAndCountFromText(value.cast<std::string>(), key, most);
    if (std::string_view(key) == "isosurfaces") {
      views.isosurfaces.emplace();
      views.isosurfaces->field = field;
      if (count) views.isosurfaces->count = *count;
    } else {
      views.streamlines.emplace();
      views.streamlines->field = field;
      if (count) views.streamlines->count = *count;
    }
    return views;
  }
  if (!py::isinstance<py::dict>(value))
    throw py::type_error(fmt::format(
        "{}= takes 'FIELD', 'FIELD:COUNT' or a dict of the scene file's keys, e.g. {}", key, example));
  toml::table mesh;
  mesh.insert(key, std::get<toml::table>(tomlValue(value, key)));
  MeshInstance instance;
  readVolumeViewKeys(TomlTableReader(mesh, "", key, SceneTable::Mesh), instance);
  return instance.volume;
}

}  // namespace

toml::table keywordTable(const py::dict& keys, const std::string& name) {
  toml::table table;
  for (const auto& [key, value] : keys) {
    if (value.is_none()) continue;  // None: not given, as everywhere in the module
    const std::string text = key.cast<std::string>();
    std::visit([&](auto&& v) { table.insert_or_assign(text, std::forward<decltype(v)>(v)); },
               tomlValue(value, fmt::format("{}({}", name, text)));
  }
  return table;
}

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
  if (arguments.arrows && !arguments.arrows.is_none()) {
    // A field's name (--arrows), or a dict of the scene keys ({'field': 'e', 'grid': [8, 8, 8]}).
    if (py::isinstance<py::str>(arguments.arrows) && arguments.arrows.cast<std::string>().empty())
      throw py::value_error("arrows='': give the name of a vector field");
    toml::table mesh;
    mesh.insert("arrows", keyTable(arguments.arrows, "arrows", "{'field': 'e', 'grid': [8, 8, 8]}"));
    if (std::optional<ArrowSpec> arrows =
            readArrows("arrows", TomlTableReader(mesh, "", "arrows", SceneTable::Mesh)))
      overrides.annotations.push_back(std::move(*arrows));
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
  applyVolumeArguments(arguments, overrides);
}

void applyVolumeArguments(const RenderArguments& arguments, RenderOverrides& overrides) {
  if (arguments.slices && !arguments.slices.is_none()) applySlicesArgument(arguments.slices, overrides);
  if (arguments.skin) {
    const auto* found = std::find(kSkinStyles.begin(), kSkinStyles.end(), *arguments.skin);
    if (found == kSkinStyles.end())
      throw py::value_error(fmt::format(
          "skin='{}' is not a skin style: use 'shown', 'ghost', 'edges' or 'hidden'", *arguments.skin));
    overrides.skin = static_cast<SkinStyle>(found - kSkinStyles.begin());
  }
  if (arguments.isosurfaces && !arguments.isosurfaces.is_none())
    overrides.isosurfaces = volumeKeyArgument(arguments.isosurfaces, "isosurfaces", kMaxIsosurfaces,
                                              "{'field': 'v', 'values': [-0.5, 0.5], 'color_by': 'e'}")
                                .isosurfaces;
  if (arguments.streamlines && !arguments.streamlines.is_none())
    overrides.streamlines =
        volumeKeyArgument(arguments.streamlines, "streamlines", kMaxStreamlines,
                          "{'field': 'e', 'count': 40, 'seed_line': [[0, 0, 0], [1, 0, 0]]}")
            .streamlines;
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
  for (AnnotationSpec& annotation : readAnnotations(kWhere, reader)) setAnnotation(instance, annotation);
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
