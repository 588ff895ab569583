// The colour maps' data: matplotlib's tables, gmsh's maps by View.ColormapNumber and the CSS colour
// names, generated into color_map_tables.cpp by scripts/make_color_maps.py (color_map.hpp uses them).
#pragma once

#include <span>
#include <string_view>

namespace lancer {

// One map: its colours as 8-bit display values, "rrggbb" each, evenly spaced from the map's low end
// (the first) to its high end (the last); 255 to 510 of them.
struct ColorTable {
  std::string_view name;  // "viridis", "RdBu", "gmsh:2"
  std::string_view hex;
};

// matplotlib's maps (in the order messages list them), then gmsh:0 to gmsh:24.
std::span<const ColorTable> colorTables();

// A CSS colour name ("navy", "darkred") and its "rrggbb"; sorted by name.
struct NamedColor {
  std::string_view name;
  std::string_view hex;
};
std::span<const NamedColor> cssColors();

}  // namespace lancer
