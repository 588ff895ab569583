// The parts color_map_tables.cpp joins: each generated source of tables (scripts/make_color_maps.py)
// gives its own, so that no source holds all the data.
#pragma once

#include <span>

#include "lancer/image/color_map_tables.hpp"

namespace lancer::color_tables {

std::span<const ColorTable> matplotlibSequential();          // viridis .. cubehelix
std::span<const ColorTable> matplotlibDivergingAndCyclic();  // coolwarm .. twilight
std::span<const ColorTable> gmshMaps();                      // gmsh:0 .. gmsh:24
std::span<const NamedColor> cssColorNames();                 // sorted by name

}  // namespace lancer::color_tables
