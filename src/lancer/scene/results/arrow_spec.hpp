// What a [[mesh]]'s `arrows` asks for (read by arrows.hpp's readArrows), kept apart from the reading
// so that the scene description does not pull in the TOML parser.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "lancer/math/vec3.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

// `arrows = { field = "velocity", max_count = 500, scale = "auto" }` on a [[mesh]]: 3D arrows (real
// triangles: they shade, cast shadows and show in mirrors) along a vector field, at most maxCount
// of them, one per cell of a grid over the surface; or, with `grid = [nx, ny, nz]`, one at each
// cell centre of a regular grid over the volume's bounds that lies inside a volume element.
struct ArrowSpec {
  std::string field;
  std::optional<int> step;  // pins the arrows to one step; default: the scene's step or time
  int maxCount = 500;
  std::optional<std::array<int, 3>> grid;  // through the volume: that many points along x, y and z
  std::optional<double> scale;  // length per unit of magnitude; default ("auto"): the longest is 0.9 cells
  // Every arrow 0.8 cells long (`length = "fixed"`), or lengths that follow the magnitude (`length =
  // "magnitude"`). Default: fixed on a grid through the volume unless a `scale` is given (a field
  // concentrated near a point, as most are inside a volume, would leave most arrows below a pixel:
  // the magnitude shows in their colour, as ParaView's Glyph draws them), the magnitude on a surface.
  std::optional<bool> fixedLength;
  bool drawsFixedLength() const { return fixedLength.value_or(grid.has_value() && !scale.has_value()); }
  std::optional<Vec3> color;  // default: coloured by magnitude
  SourceLocation where;       // the arrows value
};

}  // namespace lancer
