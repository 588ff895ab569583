// Colour maps: the published end and middle colours, monotonic lightness where the map promises it,
// clamping.
#include <gtest/gtest.h>

#include <cmath>

#include "lancer/image/color_map.hpp"

namespace lancer {
namespace {

void expectColour(const Vec3& c, int r, int g, int b) {
  EXPECT_NEAR(c.x * 255, r, 0.51);
  EXPECT_NEAR(c.y * 255, g, 0.51);
  EXPECT_NEAR(c.z * 255, b, 0.51);
}

// Rec. 709 luma of display values: a proxy for lightness, enough to check monotonic maps.
float luma(const Vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

TEST(ColorMap, EndsAndMiddleAreThePublishedColours) {
  expectColour(colorMapLookup(ColorMapKind::Viridis, 0), 68, 1, 84);        // #440154
  expectColour(colorMapLookup(ColorMapKind::Viridis, 0.5f), 33, 145, 140);  // #21918c
  expectColour(colorMapLookup(ColorMapKind::Viridis, 1), 253, 231, 37);     // #fde725
  expectColour(colorMapLookup(ColorMapKind::Magma, 0), 0, 0, 4);
  expectColour(colorMapLookup(ColorMapKind::Magma, 1), 252, 253, 191);
  expectColour(colorMapLookup(ColorMapKind::Coolwarm, 0), 59, 76, 192);
  expectColour(colorMapLookup(ColorMapKind::Coolwarm, 0.5f), 221, 221, 221);
  expectColour(colorMapLookup(ColorMapKind::Coolwarm, 1), 180, 4, 38);
  expectColour(colorMapLookup(ColorMapKind::Grey, 0.5f), 128, 128, 128);
}

TEST(ColorMap, SequentialMapsGetLighterEverywhere) {
  for (ColorMapKind kind : {ColorMapKind::Viridis, ColorMapKind::Magma, ColorMapKind::Grey}) {
    float previous = -1;
    for (int i = 0; i <= 256; ++i) {
      const float l = luma(colorMapLookup(kind, i / 256.0f));
      EXPECT_GT(l, previous) << colorMapName(kind) << " at " << i;
      previous = l;
    }
  }
}

TEST(ColorMap, DivergingMapIsLightestInTheMiddleBlueBelowRedAbove) {
  const float middle = luma(colorMapLookup(ColorMapKind::Coolwarm, 0.5f));
  for (int i = 0; i < 16; ++i) {
    const float t = i / 32.0f;
    EXPECT_LT(luma(colorMapLookup(ColorMapKind::Coolwarm, t)), middle);
    EXPECT_LT(luma(colorMapLookup(ColorMapKind::Coolwarm, 1 - t)), middle);
    const Vec3 below = colorMapLookup(ColorMapKind::Coolwarm, t),
               above = colorMapLookup(ColorMapKind::Coolwarm, 1 - t);
    EXPECT_GT(below.z, below.x);
    EXPECT_GT(above.x, above.z);
  }
}

TEST(ColorMap, OutOfRangeAndNanAreClamped) {
  EXPECT_EQ(colorMapLookup(ColorMapKind::Viridis, -3), colorMapLookup(ColorMapKind::Viridis, 0));
  EXPECT_EQ(colorMapLookup(ColorMapKind::Viridis, 7), colorMapLookup(ColorMapKind::Viridis, 1));
  EXPECT_EQ(colorMapLookup(ColorMapKind::Magma, std::nanf("")), colorMapLookup(ColorMapKind::Magma, 0));
}

TEST(ColorMap, NamesRoundTripAndUnknownIsRefused) {
  for (ColorMapKind kind :
       {ColorMapKind::Viridis, ColorMapKind::Magma, ColorMapKind::Coolwarm, ColorMapKind::Grey})
    EXPECT_EQ(parseColorMap(colorMapName(kind)), kind);
  EXPECT_EQ(parseColorMap("gray"), ColorMapKind::Grey);
  EXPECT_FALSE(parseColorMap("jet").has_value());
  EXPECT_FALSE(parseColorMap("Viridis").has_value());
}

}  // namespace
}  // namespace lancer
