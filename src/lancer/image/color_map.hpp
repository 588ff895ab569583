// Colour maps for field data (`color_by`): a scalar in [0, 1] to an RGB reflectance (the legends
// that show them: legend.hpp). The tables are matplotlib's and gmsh's own (color_map_tables.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lancer/math/vec3.hpp"

namespace lancer {

// The maps lancer's own code names: the default (viridis) and a few others; every map, these
// included, also has a name (ColorMap::named).
enum class ColorMapKind { Viridis, Magma, Coolwarm, Grey };

// A colour map ready for lookups: colours evenly spaced from t = 0 to t = 1, as 8-bit-display values
// in [0, 1], interpolated linearly in between. These maps are defined on screen values, so with
// lancer's default linear output a field renders in exactly the map's published colours (with
// --srgb the caller decodes them first). Compares equal to a map of the same name and colours.
class ColorMap {
 public:
  ColorMap() : ColorMap(ColorMapKind::Viridis) {}
  ColorMap(ColorMapKind kind);  // NOLINT(google-explicit-constructor): a kind is a map

  // A map by name: one of colorMapNames() (matplotlib's names, "grey" for "gray", "gmsh:N" for gmsh's
  // View.ColormapNumber N), any of them with "_r" for the reversed map; nullopt otherwise.
  static std::optional<ColorMap> named(std::string_view name);
  // Two or more colours evenly spaced from the low end to the high end, interpolated linearly in
  // display values (matplotlib's LinearSegmentedColormap.from_list). `name`: how messages call it.
  static ColorMap fromColors(std::vector<Vec3> colors, std::string name);

  const std::string& name() const { return name_; }
  std::span<const Vec3> colors() const { return colors_; }
  // The same colours from high to low, named NAME_r (and NAME_r's reversal is NAME).
  ColorMap reversed() const;

  // Colour at t (clamped to [0, 1]; NaN maps to 0). At t = i / (n - 1) it is colour i exactly, which
  // is what matplotlib's cmap(t) gives there for its n-colour table.
  Vec3 operator()(float t) const;

  bool operator==(const ColorMap& other) const = default;

 private:
  ColorMap(std::string name, std::vector<Vec3> colors) : name_(std::move(name)), colors_(std::move(colors)) {}
  std::string name_;
  std::vector<Vec3> colors_;
};

// Every name ColorMap::named accepts without "_r": matplotlib's maps, "grey", then gmsh:0 to gmsh:24.
std::vector<std::string_view> colorMapNames();
// For messages: "viridis, plasma, ..., twilight (matplotlib's), gmsh:0 to gmsh:24 (gmsh's
// View.ColormapNumber); NAME_r reverses any".
std::string describeColorMaps();

// A colour written as text: "#rrggbb", "#rgb" or a CSS colour name ("navy", "white"; any case);
// display values in [0, 1]. nullopt otherwise.
std::optional<Vec3> parseColor(std::string_view text);
// The CSS colour names parseColor accepts, for suggestions.
std::vector<std::string_view> colorNames();

// How values are placed on a map between the ends of their range: in proportion to the value, or to
// its logarithm (`scale = "log"`: the range's ends > 0; values at or below the low end, zero and
// negative ones included, are drawn at it).
enum class ColorScale { Linear, Log };

// Whether a field's range [low, high] is one value: low == high, or no wider than the rounding of
// its 32-bit float values (about 8 units in their last place, relative 1e-6): the length of unit
// vectors computed from rounded components spans 0.99999994..1, which is a constant field, not a
// range to spread a colour map over or to label with eight decimals.
inline bool rangeIsOneValue(double low, double high) {
  constexpr double kFloatRounding = 1e-6;
  if (!(high > low)) return true;
  const double width = high - low;
  return std::isfinite(width) && width <= kFloatRounding * std::max(std::abs(low), std::abs(high));
}

// Where a value lies on a colour map spanning [low, high]: (value - low) / (high - low), or
// (log value - log low) / (log high - log low), clamped to [0, 1]; the middle of the map when the
// range is one value (a constant field: rangeIsOneValue), NaN for NaN.
class MapPosition {
 public:
  MapPosition(double low, double high, ColorScale scale = ColorScale::Linear)
      : log_(scale == ColorScale::Log && low > 0),
        low_(log_ ? std::log(low) : low),
        scale_(rangeIsOneValue(low, high) ? 0.0 : 1.0 / ((log_ ? std::log(high) : high) - low_)) {}
  float operator()(double value) const {
    if (std::isnan(value)) return NAN;
    if (scale_ == 0) return 0.5f;
    if (log_) value = value > 0 ? std::log(value) : low_;
    return static_cast<float>(std::clamp((value - low_) * scale_, 0.0, 1.0));
  }

 private:
  bool log_;
  double low_, scale_;
};

// The colour of `kind` at t (ColorMap(kind)(t), without building the map each time).
Vec3 colorMapLookup(ColorMapKind kind, float t);

}  // namespace lancer
