// What a [[mesh]]'s `color_by` asks for (read by color_by.hpp's readColorBy), kept apart from the
// reading so that the scene description does not pull in the TOML parser.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "lancer/image/color_map.hpp"
#include "lancer/mesh/field_steps.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

struct ColorBy {
  std::string field;
  std::optional<int> step;  // pins this mesh's colours to one step; default: the scene's step or time
  ColorMapKind map = ColorMapKind::Viridis;
  std::optional<std::pair<double, double>> range;  // default: the field's range over every step
  bool perStepRange = false;                       // range = "step": the range of the step shown
  FieldComponent component;                        // component = "magnitude" (default), 0..8, "x", ...
  SourceLocation where;                            // the color_by value, for errors found at load
  // From a gmsh view's options (--gmsh-view): View[i].IntervalsType (1 iso-values, 2 continuous, 3
  // discrete bands, 4 numeric) with NbIso, and ShowScale, for isolines, bands and the legend.
  int gmshIntervalsType = 2;
  int gmshNbIso = 10;
  bool showScale = true;
};

}  // namespace lancer
