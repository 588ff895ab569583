// `color_by = { field = "temperature", step = 0, map = "viridis", range = [min, max] | "step",
// component = "magnitude" }` on a
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
#include "lancer/scene/color_by_spec.hpp"
#include "lancer/scene/toml_table_reader.hpp"

namespace lancer {

// The mesh table's `color_by`, if present (file: the scene file's path, for messages).
std::optional<ColorBy> readColorBy(const std::string& file, const TomlTableReader& mesh);

// Why [low, high] cannot be a colour range (two finite numbers, low < high), in a message naming it
// `name` ("mesh[0].color_by.range", "--range"); empty when it can. The scene file and the command
// line both ask it.
std::string colorRangeProblem(std::string_view name, double low, double high);

// A legend's title for `component` of the field `name` of `components` values, as a reader of the
// picture says it: "T" for a scalar, "|b|" for a magnitude, "sigma (von Mises)", "u (x)", "sigma (xy)".
std::string fieldTitle(const std::string& name, const FieldComponent& component, int components);

// Where a value lies on a colour map spanning [low, high]: (value - low) / (high - low) clamped to
// [0, 1], the middle of the map when the range is one value (a constant field), NaN for NaN.
class MapPosition {
 public:
  MapPosition(double low, double high) : low_(low), scale_(high > low ? 1.0 / (high - low) : 0.0) {}
  float operator()(double value) const {
    return std::isnan(value) ? NAN
           : scale_ == 0     ? 0.5f
                             : static_cast<float>(std::clamp((value - low_) * scale_, 0.0, 1.0));
  }

 private:
  double low_, scale_;
};

// A field mapped for display: t = (scalar - low) / (high - low), clamped to [0, 1]; vector fields
// show spec.component (their magnitude by default). NaN where the file gives no value (drawn as the map's low
// end).
struct FieldColoring {
  ColorMapKind map = ColorMapKind::Viridis;
  FieldAt at = FieldAt::kNode;  // t per mesh vertex, per face or per face corner slot (MeshField's)
  int components = 1;           // of the field's values: what its legend's title says of the component
  double low = 0;
  double high = 1;
  std::vector<float> t;
};

// Finds the field named by `spec` in the mesh at the step `spec` pins, else at the scene's `when` (a
// step, or a time between two steps); an unknown name, step or component is an InputError at
// spec.where that lists what the file has (and the closest name).
FieldColoring resolveColorBy(const ColorBy& spec, const Mesh& mesh, const StepSelection& when = {});

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
