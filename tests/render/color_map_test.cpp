// Colour maps: the published end and middle colours, monotonic lightness where the map promises it,
// clamping, and the legend image's bar and labels.
#include <gtest/gtest.h>

#include <cmath>

#include "lancer/image/color_map.hpp"
#include "lancer/image/text.hpp"

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

TEST(ColorBar, BarRunsFromLowAtTheBottomToHighAtTheTopWithLabels) {
  const Image legend = colorBarImage(ColorMapKind::Viridis, -1.5, 2.5, 120, 300);
  ASSERT_EQ(legend.width(), 120);
  ASSERT_EQ(legend.height(), 300);
  // Sample the bar's column near the top and bottom: close to the map's ends.
  const int x = 10;
  const Vec3 top = legend.at(x, 8).rgb(), bottom = legend.at(x, 291).rgb();
  EXPECT_LT(length(top - colorMapLookup(ColorMapKind::Viridis, 1)), 0.03f);
  EXPECT_LT(length(bottom - colorMapLookup(ColorMapKind::Viridis, 0)), 0.03f);
  // Labels: ink to the right of the bar on the rows of the end ticks, paper between labels.
  int inkPixels = 0;
  for (int y = 0; y < legend.height(); ++y)
    for (int xx = 45; xx < legend.width(); ++xx) inkPixels += legend.at(xx, y).r < 0.5f ? 1 : 0;
  EXPECT_GT(inkPixels, 5 * 20);  // five labels of at least a few glyph pixels each
  EXPECT_EQ(legend.at(legend.width() - 1, legend.height() / 2 - 20).r, 1.0f);
}

// Ink pixels right of the bar (120 wide: the bar ends at x = 32), the ticks and labels.
int labelInk(const Image& legend) {
  int ink = 0;
  for (int y = 0; y < legend.height(); ++y)
    for (int x = 32; x < legend.width(); ++x) ink += legend.at(x, y).r < 0.5f ? 1 : 0;
  return ink;
}

// A constant field is labelled once, at the middle tick, and its bar is the one colour the field
// is drawn in (the map's middle); five equal labels were drawn before.
TEST(ColorBar, ConstantFieldIsLabelledOnce) {
  const Image legend = colorBarImage(ColorMapKind::Viridis, 2.5, 2.5, 120, 300);
  Image text(120, 300);
  for (int y = 0; y < 300; ++y)
    for (int x = 0; x < 120; ++x) text.at(x, y) = {1, 1, 1, 1};
  defaultFont().draw(text, 50, 30, "2.5", 300 / 24.0f);  // anywhere right of the bar, at the legend's size
  const int tickPixels = 3;                              // 3 * scale pixels of tick, scale 1 at 300 rows
  EXPECT_EQ(labelInk(legend), labelInk(text) + tickPixels);
  for (int y : {8, 150, 291})
    EXPECT_LT(length(legend.at(10, y).rgb() - colorMapLookup(ColorMapKind::Viridis, 0.5f)), 1e-6f);
  // A range narrower than the labels' four digits reads as one number too.
  EXPECT_EQ(labelInk(colorBarImage(ColorMapKind::Viridis, 1.0, 1.000001, 120, 300)),
            labelInk(colorBarImage(ColorMapKind::Viridis, 1.0, 1.0, 120, 300)));
  // A real range keeps its five labels.
  EXPECT_GT(labelInk(colorBarImage(ColorMapKind::Viridis, 2.5, 12.5, 120, 300)), 4 * labelInk(legend));
}

}  // namespace
}  // namespace lancer
