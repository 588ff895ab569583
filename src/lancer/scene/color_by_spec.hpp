// What a [[mesh]]'s `color_by` asks for (read by color_by.hpp's readColorBy), kept apart from the
// reading so that the scene description does not pull in the TOML parser.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "lancer/image/color_map.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

struct ColorBy {
  std::string field;
  int step = 0;
  ColorMapKind map = ColorMapKind::Viridis;
  std::optional<std::pair<double, double>> range;  // default: the field's range over the step
  SourceLocation where;                            // the color_by value, for errors found at load
};

}  // namespace lancer
