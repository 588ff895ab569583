#include "lancer/image/color_map.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

#include "lancer/image/color_map_tables.hpp"

namespace lancer {
namespace {

constexpr std::string_view kReversed = "_r";
constexpr std::string_view kGmshPrefix = "gmsh:";

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

// "rrggbb..." (valid hex, a multiple of six digits) as display values in [0, 1].
std::vector<Vec3> colorsOf(std::string_view hex) {
  std::vector<Vec3> colors;
  colors.reserve(hex.size() / 6);
  auto channel = [&](std::size_t at) {
    return static_cast<float>(16 * hexDigit(hex[at]) + hexDigit(hex[at + 1])) / 255.0f;
  };
  for (std::size_t i = 0; i + 6 <= hex.size(); i += 6)
    colors.push_back({channel(i), channel(i + 2), channel(i + 4)});
  return colors;
}

const ColorTable* findTable(std::string_view name) {
  if (name == "grey") name = "gray";
  for (const ColorTable& table : colorTables())
    if (table.name == name) return &table;
  return nullptr;
}

std::string_view kindName(ColorMapKind kind) {
  switch (kind) {
    case ColorMapKind::Viridis:
      return "viridis";
    case ColorMapKind::Magma:
      return "magma";
    case ColorMapKind::Coolwarm:
      return "coolwarm";
    case ColorMapKind::Grey:
      return "gray";
  }
  return "viridis";
}

bool equalIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

}  // namespace

ColorMap::ColorMap(ColorMapKind kind) {
  const ColorTable* table = findTable(kindName(kind));
  name_ = std::string(table->name);
  colors_ = colorsOf(table->hex);
}

std::optional<ColorMap> ColorMap::named(std::string_view name) {
  const bool reversed = name.size() > kReversed.size() && name.ends_with(kReversed);
  const std::string_view base = reversed ? name.substr(0, name.size() - kReversed.size()) : name;
  const ColorTable* table = findTable(base);
  if (!table) return std::nullopt;
  ColorMap map(std::string(table->name), colorsOf(table->hex));
  return reversed ? map.reversed() : map;
}

ColorMap ColorMap::fromColors(std::vector<Vec3> colors, std::string name) {
  return ColorMap(std::move(name), std::move(colors));
}

ColorMap ColorMap::reversed() const {
  const std::string_view name = name_;
  const bool wasReversed = name.size() > kReversed.size() && name.ends_with(kReversed);
  ColorMap map(wasReversed ? std::string(name.substr(0, name.size() - kReversed.size()))
                           : name_ + std::string(kReversed),
               colors_);
  std::reverse(map.colors_.begin(), map.colors_.end());
  return map;
}

Vec3 ColorMap::operator()(float t) const {
  t = std::isnan(t) ? 0.0f : std::clamp(t, 0.0f, 1.0f);
  const int last = static_cast<int>(colors_.size()) - 1;
  const float position = t * static_cast<float>(last);
  const int index = std::min(static_cast<int>(position), last - 1);
  const float f = position - static_cast<float>(index);
  const Vec3& a = colors_[static_cast<std::size_t>(index)];
  const Vec3& b = colors_[static_cast<std::size_t>(index) + 1];
  return a + (b - a) * f;
}

std::vector<std::string_view> colorMapNames() {
  std::vector<std::string_view> names;
  for (const ColorTable& table : colorTables()) {
    names.push_back(table.name);
    if (table.name == "gray") names.push_back("grey");
  }
  return names;
}

std::string describeColorMaps() {
  std::string text;
  for (const ColorTable& table : colorTables()) {
    if (table.name.starts_with(kGmshPrefix)) continue;
    if (!text.empty()) text += ", ";
    text += table.name;
  }
  return text + " (matplotlib's), gmsh:0 to gmsh:24 (gmsh's View.ColormapNumber); NAME_r reverses any";
}

std::optional<Vec3> parseColor(std::string_view text) {
  if (text.starts_with('#')) {
    const std::string_view digits = text.substr(1);
    if (digits.size() != 3 && digits.size() != 6) return std::nullopt;
    if (!std::all_of(digits.begin(), digits.end(), [](char c) { return hexDigit(c) >= 0; }))
      return std::nullopt;
    if (digits.size() == 6) return colorsOf(digits).front();
    const std::string doubled{digits[0], digits[0], digits[1], digits[1], digits[2], digits[2]};
    return colorsOf(doubled).front();
  }
  for (const NamedColor& color : cssColors())
    if (equalIgnoringCase(color.name, text)) return colorsOf(color.hex).front();
  return std::nullopt;
}

std::vector<std::string_view> colorNames() {
  std::vector<std::string_view> names;
  for (const NamedColor& color : cssColors()) names.push_back(color.name);
  return names;
}

Vec3 colorMapLookup(ColorMapKind kind, float t) {
  static const std::array<ColorMap, 4> kMaps = {
      ColorMap(ColorMapKind::Viridis), ColorMap(ColorMapKind::Magma), ColorMap(ColorMapKind::Coolwarm),
      ColorMap(ColorMapKind::Grey)};
  return kMaps[static_cast<std::size_t>(kind)](t);
}

}  // namespace lancer
