#include "lancer/image/color_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace lancer {
namespace {

// Nine evenly spaced samples (t = 0, 1/8, ..., 1) of each map as 8-bit sRGB triples, interpolated
// linearly between samples. viridis and magma: matplotlib's `cm.<name>(np.linspace(0, 1, 9))`;
// the piecewise-linear curve stays within a few 1/255 of the 256-entry tables. coolwarm: Kenneth
// Moreland, "Diverging Color Maps for Scientific Visualization" (2009), sampled the same way.
using ColorTable = std::array<std::array<unsigned char, 3>, 9>;

constexpr ColorTable kViridis = {{{68, 1, 84},
                                  {71, 45, 123},
                                  {59, 82, 139},
                                  {44, 114, 142},
                                  {33, 145, 140},
                                  {40, 174, 128},
                                  {94, 201, 98},
                                  {173, 220, 48},
                                  {253, 231, 37}}};
constexpr ColorTable kMagma = {{{0, 0, 4},
                                {28, 16, 68},
                                {79, 18, 123},
                                {129, 37, 129},
                                {181, 54, 122},
                                {229, 80, 100},
                                {251, 135, 97},
                                {254, 194, 135},
                                {252, 253, 191}}};
constexpr ColorTable kCoolwarm = {{{59, 76, 192},
                                   {98, 130, 234},
                                   {141, 176, 254},
                                   {184, 208, 249},
                                   {221, 221, 221},
                                   {245, 196, 173},
                                   {244, 154, 123},
                                   {222, 96, 77},
                                   {180, 4, 38}}};

Vec3 interpolate(const ColorTable& table, float t) {
  const float position = t * static_cast<float>(table.size() - 1);
  const int index = std::min(static_cast<int>(position), static_cast<int>(table.size()) - 2);
  const float f = position - static_cast<float>(index);
  const auto& a = table[static_cast<std::size_t>(index)];
  const auto& b = table[static_cast<std::size_t>(index) + 1];
  auto channel = [f](unsigned char x, unsigned char y) {
    return (static_cast<float>(x) + f * (static_cast<float>(y) - static_cast<float>(x))) * (1.0f / 255.0f);
  };
  return {channel(a[0], b[0]), channel(a[1], b[1]), channel(a[2], b[2])};
}

}  // namespace

std::optional<ColorMapKind> parseColorMap(std::string_view name) {
  if (name == "viridis") return ColorMapKind::Viridis;
  if (name == "magma") return ColorMapKind::Magma;
  if (name == "coolwarm") return ColorMapKind::Coolwarm;
  if (name == "grey" || name == "gray") return ColorMapKind::Grey;
  return std::nullopt;
}

std::string_view colorMapName(ColorMapKind kind) {
  switch (kind) {
    case ColorMapKind::Viridis:
      return "viridis";
    case ColorMapKind::Magma:
      return "magma";
    case ColorMapKind::Coolwarm:
      return "coolwarm";
    case ColorMapKind::Grey:
      return "grey";
  }
  return "viridis";
}

std::string_view colorMapNames() { return "viridis, magma, coolwarm, grey"; }

Vec3 colorMapLookup(ColorMapKind kind, float t) {
  t = std::isnan(t) ? 0.0f : std::clamp(t, 0.0f, 1.0f);
  switch (kind) {
    case ColorMapKind::Viridis:
      return interpolate(kViridis, t);
    case ColorMapKind::Magma:
      return interpolate(kMagma, t);
    case ColorMapKind::Coolwarm:
      return interpolate(kCoolwarm, t);
    case ColorMapKind::Grey:
      return {t, t, t};
  }
  return {t, t, t};
}

}  // namespace lancer
