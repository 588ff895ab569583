// Colour maps for field data (`color_by`): a scalar in [0, 1] to an RGB reflectance (the legends
// that show them: legend.hpp).
#pragma once

#include <optional>
#include <string_view>

#include "lancer/image/image.hpp"
#include "lancer/math/vec3.hpp"

namespace lancer {

// viridis and magma (perceptually uniform, matplotlib's), coolwarm (Moreland's diverging map,
// for signed fields), grey (black to white).
enum class ColorMapKind { Viridis, Magma, Coolwarm, Grey };

// Parses "viridis", "magma", "coolwarm", "grey" (or "gray"); nullopt otherwise.
std::optional<ColorMapKind> parseColorMap(std::string_view name);
std::string_view colorMapName(ColorMapKind kind);
// The names parseColorMap accepts, for error messages: "viridis, magma, coolwarm, grey".
std::string_view colorMapNames();

// Colour at t (clamped to [0, 1]; NaN maps to 0), as 8-bit-display values in [0, 1]: these maps
// are defined on screen values, so with lancer's default linear output a field renders in exactly
// the map's published colours (with --srgb the caller decodes them first).
Vec3 colorMapLookup(ColorMapKind kind, float t);

}  // namespace lancer
