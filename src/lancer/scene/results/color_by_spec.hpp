// What a [[mesh]]'s `color_by` asks for (read by color_by.hpp's readColorBy), kept apart from the
// reading so that the scene description does not pull in the TOML parser.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lancer/image/color_map.hpp"
#include "lancer/image/legend.hpp"
#include "lancer/math/vec3.hpp"
#include "lancer/mesh/field_steps.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

struct ColorBy {
  std::string field;
  std::optional<int> step;  // pins this mesh's colours to one step; default: the scene's step or time
  ColorMap map;             // map = "viridis" (default), "RdBu_r", "gmsh:2", [colours]
  ColorScale scale = ColorScale::Linear;           // scale = "log": values placed by their logarithm
  std::optional<std::pair<double, double>> range;  // default: the field's range over every step
  bool perStepRange = false;                       // range = "step": the range of the step shown
  FieldComponent component;                        // component = "magnitude" (default), 0..8, "x", ...
  SourceLocation where;                            // the color_by value, for errors found at load
  // The front end's option that asked for the log scale ("--log", Python's "log"), which its errors
  // name instead of the scene key; empty for the key.
  std::string logOption;
  std::optional<std::string> title;       // the legend's; default: the field's name
  std::string units;                      // the legend's, after the title
  int bands = 0;                          // > 0: that many discrete colour bands
  std::optional<LegendPlacement> legend;  // legends in the picture; default: none
  // False for gmsh's iso-values view (View.IntervalsType = 1, --gmsh-view): the range and legend
  // hold, the surface keeps its material, and the isolines take the map's colours.
  bool paintsSurface = true;
  // False on a mesh that paints nothing and carries the colours' options (map, range, legend) for
  // the arrows of a field it is not coloured by (a skin drawn as a ghost, an uncoloured mesh given
  // --legend): the arrows draw the legend, over their own range; the mesh adds none and its range
  // is not merged with others'.
  bool ownLegend = true;
};

// `isolines = { field = "T", count = 10 }` (or `values = [...]`) on a [[mesh]]: the curves where a
// node field, interpolated over each face, takes the given values, drawn `widthPixels` wide.
struct IsolineSpec {
  std::string field;
  std::optional<int> step;     // pins the lines to one step; default: the scene's step or time
  FieldComponent component;    // of a vector or tensor field: its magnitude by default
  int count = 10;              // evenly spaced inside the field's range, when `values` is empty
  std::vector<double> values;  // explicit values
  // gmsh's iso-values (View.IntervalsType = 1, --gmsh-view): `count` values from the low end of the
  // mesh's colour range to its high end, both included (one value, the middle, when count is 1).
  bool colorRangeEnds = false;
  Vec3 color{0, 0, 0};
  // color = "map": each line in the colour of its value in the mesh's colour map (its color_by of
  // the same field and component, else the default map over the lines' values).
  bool colorFromMap = false;
  float widthPixels = 1.5f;
  SourceLocation where;  // the isolines value
};

}  // namespace lancer
