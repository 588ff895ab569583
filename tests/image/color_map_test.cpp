// Colour maps: matplotlib's published colours at the ends and middles, monotonic lightness where the
// map promises it, reversal, gmsh's maps, lists of colours, colour names, clamping, and where values
// fall on a log scale. (tests/python/test_color_maps.py compares every table with matplotlib's and
// gmsh's own.)
#include "lancer/image/color_map.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "lancer/image/color_map_tables.hpp"
#include "lancer/image/pixel_encoding.hpp"

namespace lancer {
namespace {

// Within 1/255 of an 8-bit colour (matplotlib's cmap(t) rounded).
void expectColour(const Vec3& c, int r, int g, int b) {
  EXPECT_NEAR(c.x * 255, r, 1.0);
  EXPECT_NEAR(c.y * 255, g, 1.0);
  EXPECT_NEAR(c.z * 255, b, 1.0);
}

ColorMap named(std::string_view name) {
  const std::optional<ColorMap> map = ColorMap::named(name);
  EXPECT_TRUE(map) << name;
  return map.value_or(ColorMap{});
}

// CIE L* of display values (sRGB decoded, Rec. 709 luminance): the lightness perceptually uniform
// maps increase evenly.
float lightness(const Vec3& c) {
  const float y =
      0.2126f * linearFromSrgb(c.x) + 0.7152f * linearFromSrgb(c.y) + 0.0722f * linearFromSrgb(c.z);
  return y > 216.0f / 24389.0f ? 116 * std::cbrt(y) - 16 : 24389.0f / 27.0f * y;
}

TEST(ColorMap, EndsAndMiddlesAreMatplotlibsColours) {
  // matplotlib 3.6's cmap(0), cmap(0.5), cmap(1), rounded to 8 bits. matplotlib's cmap(0.5) is its
  // table's entry 128, which lancer gives at t = 128 / 255 (at 0.5 it is halfway to entry 127).
  constexpr float kMiddle = 128.0f / 255.0f;
  expectColour(colorMapLookup(ColorMapKind::Viridis, 0), 68, 1, 84);           // #440154
  expectColour(colorMapLookup(ColorMapKind::Viridis, kMiddle), 33, 145, 140);  // #21918c
  expectColour(colorMapLookup(ColorMapKind::Viridis, 1), 253, 231, 37);        // #fde725
  expectColour(colorMapLookup(ColorMapKind::Magma, 0), 0, 0, 4);
  expectColour(colorMapLookup(ColorMapKind::Magma, kMiddle), 183, 55, 121);
  expectColour(colorMapLookup(ColorMapKind::Magma, 1), 252, 253, 191);
  expectColour(colorMapLookup(ColorMapKind::Coolwarm, 0), 59, 76, 192);
  expectColour(colorMapLookup(ColorMapKind::Coolwarm, kMiddle), 221, 220, 220);
  expectColour(colorMapLookup(ColorMapKind::Coolwarm, 1), 180, 4, 38);
  expectColour(colorMapLookup(ColorMapKind::Grey, kMiddle), 128, 128, 128);
  expectColour(named("turbo")(0), 48, 18, 59);
  expectColour(named("turbo")(kMiddle), 164, 252, 60);
  expectColour(named("RdBu")(0), 103, 0, 31);
  expectColour(named("RdBu")(1), 5, 48, 97);
  expectColour(named("jet")(0), 0, 0, 128);
  expectColour(named("jet")(kMiddle), 125, 255, 122);
  expectColour(named("jet")(1), 128, 0, 0);
}

TEST(ColorMap, TablesHaveMatplotlibsResolution) {
  EXPECT_EQ(named("viridis").colors().size(), 256u);
  EXPECT_EQ(named("RdBu").colors().size(), 256u);
  EXPECT_EQ(named("twilight").colors().size(), 510u);
  EXPECT_EQ(named("gmsh:2").colors().size(), 255u);   // gmsh's View.NbColors
  EXPECT_EQ(named("gmsh:23").colors().size(), 256u);  // gmsh's copy of viridis
  // At t = i / 255 a lookup is table entry i, as matplotlib's cmap(i / 255) is.
  const ColorMap viridis = named("viridis");
  for (int i = 0; i < 256; ++i) EXPECT_EQ(viridis(static_cast<float>(i) / 255), viridis.colors()[i]) << i;
}

TEST(ColorMap, PerceptuallyUniformMapsGetLighterEverywhere) {
  // Entry by entry L* never falls by more than the 8-bit rounding can make it (0.2); over every
  // eight entries (1/32 of the map) it rises.
  for (const char* name : {"viridis", "plasma", "inferno", "magma", "cividis", "gray", "Greys_r"}) {
    const ColorMap map = named(name);  // the span is its table's: the map must outlive it
    const std::span<const Vec3> colors = map.colors();
    for (std::size_t i = 1; i < colors.size(); ++i) {
      EXPECT_GT(lightness(colors[i]), lightness(colors[i - 1]) - 0.2f) << name << " at " << i;
      if (i >= 8) {
        EXPECT_GT(lightness(colors[i]), lightness(colors[i - 8])) << name << " at " << i;
      }
    }
  }
  // viridis climbs evenly: its L* over each tenth of the map differs little from the mean climb.
  const ColorMap viridis = named("viridis");
  const float climb = (lightness(viridis(1)) - lightness(viridis(0))) / 10;
  for (int k = 0; k < 10; ++k)
    EXPECT_NEAR(lightness(viridis((k + 1) / 10.0f)) - lightness(viridis(k / 10.0f)), climb, 0.3f * climb)
        << k;
}

TEST(ColorMap, DivergingMapIsLightestInTheMiddleBlueBelowRedAbove) {
  const float middle = lightness(colorMapLookup(ColorMapKind::Coolwarm, 0.5f));
  for (int i = 0; i < 16; ++i) {
    const float t = i / 32.0f;
    const Vec3 below = colorMapLookup(ColorMapKind::Coolwarm, t),
               above = colorMapLookup(ColorMapKind::Coolwarm, 1 - t);
    EXPECT_LT(lightness(below), middle);
    EXPECT_LT(lightness(above), middle);
    EXPECT_GT(below.z, below.x);
    EXPECT_GT(above.x, above.z);
  }
}

TEST(ColorMap, ReversedMapsRunBackwards) {
  for (const char* name : {"viridis", "RdBu", "gmsh:2", "twilight"}) {
    const ColorMap map = named(name);
    const ColorMap reversed = named(std::string(name) + "_r");
    EXPECT_EQ(reversed.name(), std::string(name) + "_r");
    EXPECT_EQ(reversed, map.reversed());
    EXPECT_EQ(reversed.reversed(), map);
    for (int i = 0; i <= 64; ++i) {
      const float t = static_cast<float>(i) / 64;
      EXPECT_LT(length(reversed(t) - map(1 - t)), 1e-5f) << name << " at " << t;
    }
  }
  EXPECT_FALSE(ColorMap::named("viridis_r_r"));  // as in matplotlib
  EXPECT_FALSE(ColorMap::named("_r"));
}

TEST(ColorMap, NamesAndAliases) {
  const std::vector<std::string_view> names = colorMapNames();
  for (const char* wanted : {"viridis",  "plasma", "inferno", "magma",   "cividis",  "turbo",  "coolwarm",
                             "RdBu",     "jet",    "gray",    "grey",    "Blues",    "Reds",   "RdYlBu",
                             "Spectral", "hot",    "bwr",     "seismic", "twilight", "gmsh:0", "gmsh:24"})
    EXPECT_NE(std::find(names.begin(), names.end(), wanted), names.end()) << wanted;
  for (const std::string_view name : names) EXPECT_TRUE(ColorMap::named(name)) << name;
  EXPECT_EQ(named("grey"), named("gray"));
  EXPECT_EQ(named("grey").name(), "gray");
  EXPECT_EQ(ColorMap(ColorMapKind::Grey), named("gray"));
  EXPECT_EQ(ColorMap{}, named("viridis"));
  EXPECT_FALSE(ColorMap::named("Viridis"));  // matplotlib's names are case-sensitive
  EXPECT_FALSE(ColorMap::named("gmsh:25"));
  EXPECT_FALSE(ColorMap::named(""));
  EXPECT_NE(describeColorMaps().find("gmsh:0 to gmsh:24"), std::string::npos);
}

TEST(ColorMap, GmshsMapsAreGmshsTables) {
  // gmsh 4.8's ColorTable_Recompute: jet (its default) from dark blue (0, 0, 143) to dark red
  // (119, 0, 0); its viridis is matplotlib's truncated to integers.
  expectColour(named("gmsh:2")(0), 0, 0, 143);
  expectColour(named("gmsh:2")(1), 119, 0, 0);
  expectColour(named("gmsh:0")(0.5f), 0, 0, 0);
  for (int i = 0; i <= 255; ++i) {
    const float t = static_cast<float>(i) / 255;
    const Vec3 difference = named("gmsh:23")(t) - named("viridis")(t);
    EXPECT_LE(std::max({std::abs(difference.x), std::abs(difference.y), std::abs(difference.z)}), 1.01f / 255)
        << i;
  }
}

TEST(ColorMap, ListsAreInterpolatedInDisplayValues) {
  const ColorMap map = ColorMap::fromColors(
      {*parseColor("#000080"), *parseColor("white"), *parseColor("#800000")}, "[#000080, white, #800000]");
  EXPECT_EQ(map.name(), "[#000080, white, #800000]");
  expectColour(map(0), 0, 0, 128);
  expectColour(map(0.5f), 255, 255, 255);
  expectColour(map(1), 128, 0, 0);
  // Halfway between navy and white, as matplotlib's LinearSegmentedColormap.from_list.
  EXPECT_LT(length(map(0.25f) - Vec3{127.5f, 127.5f, 191.5f} / 255.0f), 1e-5f);
}

TEST(ColorMap, ColoursAsText) {
  EXPECT_EQ(parseColor("#ff8000"), (Vec3{1, 128 / 255.0f, 0}));
  EXPECT_EQ(parseColor("#FF8000"), parseColor("#ff8000"));
  EXPECT_EQ(parseColor("#f80"), (Vec3{1, 136 / 255.0f, 0}));
  EXPECT_EQ(parseColor("navy"), (Vec3{0, 0, 128 / 255.0f}));
  EXPECT_EQ(parseColor("White"), (Vec3{1, 1, 1}));
  EXPECT_EQ(parseColor("grey"), parseColor("gray"));
  for (const char* bad : {"", "#", "#12345", "#ggg", "whte", "0x000080"})
    EXPECT_FALSE(parseColor(bad)) << bad;
  EXPECT_EQ(colorNames().size(), cssColors().size());
}

TEST(ColorMap, OutOfRangeAndNanAreClamped) {
  EXPECT_EQ(colorMapLookup(ColorMapKind::Viridis, -3), colorMapLookup(ColorMapKind::Viridis, 0));
  EXPECT_EQ(colorMapLookup(ColorMapKind::Viridis, 7), colorMapLookup(ColorMapKind::Viridis, 1));
  EXPECT_EQ(colorMapLookup(ColorMapKind::Magma, std::nanf("")), colorMapLookup(ColorMapKind::Magma, 0));
}

TEST(MapPosition, LinearAndLogPositions) {
  const MapPosition linear(1, 3);
  EXPECT_FLOAT_EQ(linear(2), 0.5f);
  EXPECT_FLOAT_EQ(linear(0), 0.0f);
  const MapPosition log(1e-3, 10, ColorScale::Log);  // four decades
  EXPECT_FLOAT_EQ(log(1e-3), 0.0f);
  EXPECT_FLOAT_EQ(log(1e-2), 0.25f);
  EXPECT_FLOAT_EQ(log(1), 0.75f);
  EXPECT_FLOAT_EQ(log(10), 1.0f);
  EXPECT_NEAR(log(std::sqrt(10.0) * 1e-3), 0.125f, 1e-6f);
  // Below the low end, zero and negative values included: the map's low end.
  EXPECT_EQ(log(1e-9), 0.0f);
  EXPECT_EQ(log(0), 0.0f);
  EXPECT_EQ(log(-5), 0.0f);
  EXPECT_EQ(log(1e9), 1.0f);
  EXPECT_TRUE(std::isnan(log(NAN)));
  EXPECT_EQ(MapPosition(2, 2, ColorScale::Log)(2), 0.5f);  // a constant field: the middle
}

}  // namespace
}  // namespace lancer
