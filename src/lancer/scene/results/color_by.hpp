// `color_by = { field = "temperature", step = 0, map = "viridis", range = [min, max] | "step",
// component = "magnitude", scale = "linear" | "log" }` on a
// [[mesh]]: colouring a surface by a field of its .msh file ($NodeData or $ElementData). Reading
// the scene key, then resolving it against the loaded mesh into normalised scalars in [0, 1] that
// the tracer maps to colours (per vertex, interpolated per pixel, or per face).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/results/color_by_spec.hpp"
#include "lancer/scene/toml_table_reader.hpp"

namespace lancer {

// The mesh table's `color_by`, if present (file: the scene file's path, for messages).
std::optional<ColorBy> readColorBy(const std::string& file, const TomlTableReader& mesh);

// Why [low, high] cannot be a colour range on `scale` (two finite numbers, low < high, low > 0 on a
// log scale), in a message naming it `name` ("mesh[0].color_by.range", "--range"); empty when it
// can. The scene file and the command line both ask it.
std::string colorRangeProblem(std::string_view name, double low, double high,
                              ColorScale scale = ColorScale::Linear);

// A legend's title for `component` of the field `name` of `components` values, as a reader of the
// picture says it: "T" for a scalar, "|b|" for a magnitude, "sigma (von Mises)", "u (x)", "sigma (xy)".
std::string fieldTitle(const std::string& name, const FieldComponent& component, int components);

// How an error about a log scale over values down to 0 names what asked for it and what to do, in
// the words of the option that asked (spec.logOption: "--log", Python's "log") or of the scene key:
// where, the scale's name, a range up to `high` that would do, and how to go back to linear.
struct LogScaleWords {
  SourceLocation where;
  std::string log, advice, linear;
};
LogScaleWords logScaleWords(const ColorBy& spec, double high);

// A field mapped for display: t = (scalar - low) / (high - low), clamped to [0, 1]; on a log scale
// the scalar itself, placed on the map after interpolation (FieldMap, MapPosition). Vector fields
// show spec.component (their magnitude by default). NaN where the file gives no value (not coloured).
struct FieldColoring {
  ColorMap map;
  ColorScale scale = ColorScale::Linear;
  FieldAt at = FieldAt::kNode;  // t per mesh vertex, per face or per face corner slot (MeshField's)
  int components = 1;           // of the field's values: what its legend's title says of the component
  double low = 0;
  double high = 1;
  std::vector<float> t;
};

// Finds the field named by `spec` in the mesh at the step `spec` pins, else at the scene's `when` (a
// step, or a time between two steps); an unknown name, step or component is an InputError at
// spec.where that lists what the file has (and the closest name), as is a log scale over a range
// that reaches 0 or below (naming the least value).
FieldColoring resolveColorBy(const ColorBy& spec, const Mesh& mesh, const StepSelection& when = {});

// A colour map as text: a name (colorMapNames(), NAME_r reversed) or two or more colours separated
// by commas ("#000080,white,#800000", as --color-map takes them). Otherwise an InputError at `where`
// (the option) that lists the maps and the closest name.
ColorMap colorMapFromText(std::string_view text, const SourceLocation& where);
// A list map's limits: matplotlib's from_list takes any number; 256 is its table's resolution.
inline constexpr std::size_t kMaxListColors = 256;
// Why `name` is not a colour map, with the closest name and the maps there are, for messages:
// "\"virdis\" is not a colour map (did you mean 'viridis'?): use viridis, ...".
std::string unknownColorMapMessage(std::string_view name);
// Why `text` is not a colour ("#rrggbb", "#rgb" or a CSS name), with the closest name.
std::string unknownColorMessage(std::string_view text);

// A table's `component` key (color_by, isolines): "magnitude", "x", "y", "z", "von_mises" or an
// index 0 to 8; nullopt when absent.
std::optional<FieldComponent> readFieldComponent(const TomlTableReader& reader);

// The field `name` at `step` of the mesh; an unknown name or step is an InputError at `where`,
// "<key> field ...", listing what the file has (and the closest name).
const MeshField& findMeshField(std::string_view key, const std::string& name, int step, const Mesh& mesh,
                               const SourceLocation& where);

// The view `name` at `step` when one is pinned, else at the scene's `when` (a blend of the two steps
// around a time); an unknown name or step is an InputError at `where` as findMeshField says it.
MeshField meshFieldAt(std::string_view key, const std::string& name, std::optional<int> step,
                      const Mesh& mesh, const StepSelection& when, const SourceLocation& where);

}  // namespace lancer
