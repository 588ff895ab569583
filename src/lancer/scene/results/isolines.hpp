// `isolines = { field = "T", count = 10 }` on a [[mesh]] (or `values = [...]`, `color`, `width`):
// reading the scene key, then resolving it against the loaded mesh into per-vertex values and the
// sorted iso values the tracer draws lines at (render/isoline_paint.hpp).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/results/color_by_spec.hpp"
#include "lancer/scene/toml_table_reader.hpp"

namespace lancer {

// The mesh table's `isolines`, if present (file: the scene file's path, for messages).
std::optional<IsolineSpec> readIsolines(const std::string& file, const TomlTableReader& mesh);

struct ResolvedIsolines {
  // Per mesh vertex (node data) or per face corner slot (element-node data, each element's own
  // values: lines break where the field jumps); NaN where the file gives none.
  FieldAt at = FieldAt::kNode;
  std::vector<float> vertexValue;
  std::vector<float> values;  // sorted, distinct
  // Element data, drawn on its mean at the vertices (elementMeansAtVertices): worth a note.
  bool fromElementData = false;
};

// Element data (one value per face) as one value per vertex: the mean of the values of the elements
// around it, each element once (the faces of a split second-order element are one element), NaN
// ignored; NaN where none gives one. ParaView's Cell Data to Point Data does the same.
std::vector<float> elementMeansAtVertices(const Mesh& mesh, const std::vector<float>& faceValues);

// The lines at the step spec pins, else at the scene's `when`. Without `values`, `count` values
// spread over the range of that step (when pinned) or of every step (as the colours), or with
// spec.colorRangeEnds over `colorRange` (the mesh's colour range, when it is coloured by the field).
// With a log `colorScale` (the mesh's colours on a log scale), the values are spread evenly in
// log(value) over `colorRange` (both ends included with colorRangeEnds, as gmsh's log scale does).
// Element data (constant over each face) has no curves of its own: its lines are those of its mean at
// the vertices (elementMeansAtVertices), at values from its own range. An unknown field, step or
// component is an InputError at spec.where as color_by says it.
ResolvedIsolines resolveIsolines(const IsolineSpec& spec, const Mesh& mesh, const StepSelection& when = {},
                                 std::optional<std::pair<double, double>> colorRange = std::nullopt,
                                 ColorScale colorScale = ColorScale::Linear);

// `count` values evenly inside (low, high): low + (high - low) * (i + 0.5) / count, one line in the
// middle of each of `count` equal intervals.
std::vector<double> evenIsoValues(double low, double high, int count);

// `count` values evenly inside (log low, log high), 0 < low: one line at the middle, in log(value),
// of each of `count` intervals equal on a log scale.
std::vector<double> logIsoValues(double low, double high, int count);

// gmsh's iso-values (PViewOptions::getScaleValue, linear scale): low + (high - low) * i / (count - 1)
// for i = 0 .. count - 1, both ends included; the middle when count is 1.
std::vector<double> gmshIsoValues(double low, double high, int count);

}  // namespace lancer
