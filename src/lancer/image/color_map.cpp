#include "lancer/image/color_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "lancer/image/text.hpp"

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

Image colorBarImage(ColorMapKind kind, double low, double high, int width, int height) {
  width = std::max(width, 48);
  height = std::max(height, 64);
  Image image(width, height);
  const Rgba paper{1, 1, 1, 1}, ink{0, 0, 0, 1};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.at(x, y) = paper;
  const Font& font = defaultFont();
  const float textHeight = std::max(12.0f, static_cast<float>(height) / 24.0f);
  const int digitHeight = font.measure("0", textHeight).inkHeight();
  const int scale = std::max(1, height / 200);
  const int margin = (digitHeight + 1) / 2 + 2;  // half a label above the top tick
  const int barLeft = 2 * scale, barRight = barLeft + std::max(4, width / 4);
  const int barTop = margin, barBottom = height - margin;
  // A constant field is drawn in the map's middle colour (color_by.cpp), so its bar is that colour.
  const bool constant = low == high;
  for (int y = barTop; y < barBottom; ++y) {
    // Row centres map the bottom row to low and the top row to high.
    const float t = 1.0f - (static_cast<float>(y - barTop) + 0.5f) / static_cast<float>(barBottom - barTop);
    const Vec3 c = colorMapLookup(kind, constant ? 0.5f : t);
    for (int x = barLeft; x < barRight; ++x) image.at(x, y) = {c.x, c.y, c.z, 1};
  }
  constexpr int kTicks = 5;
  std::array<std::string, kTicks> labels;
  for (int i = 0; i < kTicks; ++i) {
    char label[32];
    std::snprintf(label, sizeof label, "%.4g", low + static_cast<double>(i) / (kTicks - 1) * (high - low));
    labels[static_cast<std::size_t>(i)] = label;
  }
  // Five ticks that would all read the same number (a constant field, or a range below the labels'
  // four digits) are one tick, at the middle, labelled once.
  const bool oneLabel =
      std::all_of(labels.begin(), labels.end(), [&](const std::string& l) { return l == labels[0]; });
  for (int i = oneLabel ? kTicks / 2 : 0; i < (oneLabel ? kTicks / 2 + 1 : kTicks); ++i) {
    const double fraction = static_cast<double>(i) / (kTicks - 1);
    const int row = barBottom - 1 - static_cast<int>(std::lround(fraction * (barBottom - 1 - barTop)));
    const int tickEnd = barRight + 3 * scale;
    for (int x = barRight; x < std::min(width, tickEnd); ++x) image.at(x, row) = ink;
    font.draw(image, tickEnd + 2 * scale, row + digitHeight / 2, labels[static_cast<std::size_t>(i)],
              textHeight, TextStyle(ink.rgb()));
  }
  return image;
}

}  // namespace lancer
