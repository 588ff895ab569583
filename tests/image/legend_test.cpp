// Legends: Heckbert's nice tick values, their labels in one notation, titles with units, the legend
// image's bar (discrete with bands) and legends drawn into a picture.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "lancer/image/legend.hpp"

namespace lancer {
namespace {

TEST(NiceTicks, RoundStepsInsideTheRange) {
  EXPECT_EQ(niceTicks(0, 1).values, (std::vector<double>{0, 0.2, 0.4, 0.6000000000000001, 0.8, 1}));
  EXPECT_EQ(niceTicks(0, 1).step, 0.2);
  EXPECT_EQ(niceTicks(0.5, 3).values, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(niceTicks(0.5, 3, 11).values, (std::vector<double>{0.5, 1, 1.5, 2, 2.5, 3}));
  EXPECT_EQ(niceTicks(-1.5, 2.5).values, (std::vector<double>{-1, 0, 1, 2}));
  EXPECT_EQ(niceTicks(0, 350000).values, (std::vector<double>{0, 100000, 200000, 300000}));
  EXPECT_EQ(niceTicks(12.3, 87.6).step, 20);
  // A horizontal legend asks for 4: a stress range of 0..240 gets 0, 100, 200, not only 0 and 200.
  EXPECT_EQ(niceTicks(0, 240, 4).values, (std::vector<double>{0, 100, 200}));
  // Every tick a multiple of the step, 1, 2 or 5 times a power of ten, inside the range.
  for (const auto& [low, high] : std::vector<std::pair<double, double>>{
           {0.001, 0.0047}, {-273.15, 1200}, {1e5, 1.01e5}, {3.3, 3.4}, {-7e-6, 2e-6}, {0.9, 1.1}}) {
    const NiceTicks ticks = niceTicks(low, high);
    EXPECT_GE(ticks.values.size(), 2u) << low << " " << high;
    EXPECT_LE(ticks.values.size(), 11u) << low << " " << high;
    for (const double v : ticks.values) {
      EXPECT_GE(v, low - 1e-9 * (high - low));
      EXPECT_LE(v, high + 1e-9 * (high - low));
      EXPECT_NEAR(v / ticks.step, std::round(v / ticks.step), 1e-6);
    }
    const double mantissa = ticks.step / std::pow(10.0, std::floor(std::log10(ticks.step) + 1e-9));
    EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
                std::abs(mantissa - 5) < 1e-9)
        << ticks.step;
  }
}

TEST(NiceTicks, NarrowRangesStillGetTwoTicksAndConstantFieldsOne) {
  // [0.9, 1.1] has the nice step 0.05 or 0.1; [3.3, 3.4] 0.02 or 0.05: never a single tick.
  EXPECT_GE(niceTicks(3.31, 3.38).values.size(), 2u);
  EXPECT_EQ(niceTicks(2.5, 2.5).values, (std::vector<double>{2.5}));
  EXPECT_EQ(niceTicks(2.5, 2.5).step, 0);
}

TEST(NiceTicks, ARangeOfFloatRoundingIsOneCleanValue) {
  // |w| of unit vectors stored as floats: 0.99999994..1 is a constant field, not eight decimals.
  const double below = std::nextafter(1.0f, 0.0f);
  EXPECT_TRUE(rangeIsOneValue(below, 1.0));
  EXPECT_EQ(tickLabels(niceTicks(below, 1.0)), (std::vector<std::string>{"1"}));
  EXPECT_EQ(tickLabels(niceTicks(-1.0, -0.9999995)), (std::vector<std::string>{"\u22121"}));
  EXPECT_EQ(logTickLabels(logTicks(below, 1.0)), (std::vector<std::string>{"1"}));
  // The map's middle colour for every value, as for low == high.
  const MapPosition position(below, 1.0);
  EXPECT_EQ(position(below), 0.5f);
  EXPECT_EQ(position(1.0), 0.5f);
  // A range the floats do hold is spread and labelled as before.
  EXPECT_FALSE(rangeIsOneValue(0.99999, 1.0));
  EXPECT_GE(niceTicks(0.99999, 1.0).values.size(), 3u);
  EXPECT_EQ(MapPosition(0.99999, 1.0)(0.99999), 0.0f);
  EXPECT_FALSE(rangeIsOneValue(-1e-9, 1e-9));  // around zero there is no scale to round against
  EXPECT_FALSE(rangeIsOneValue(0, std::numeric_limits<double>::infinity()));
  // Its legend is the constant field's: one label, at the middle of a bar of the middle colour.
  const LegendSpec rounded{ColorMapKind::Viridis, below, 1.0, "|w|", "", 0};
  const LegendSpec constant{ColorMapKind::Viridis, 1.0, 1.0, "|w|", "", 0};
  const Image a = legendImage(rounded, false, 120, 14, false),
              b = legendImage(constant, false, 120, 14, false);
  ASSERT_EQ(a.width(), b.width());
  ASSERT_EQ(a.height(), b.height());
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) ASSERT_TRUE(a.at(x, y) == b.at(x, y)) << x << "," << y;
}

TEST(TickLabels, OneNotationWithTheDigitsTheStepNeeds) {
  EXPECT_EQ(tickLabels(niceTicks(0.5, 3, 11)),
            (std::vector<std::string>{"0.5", "1.0", "1.5", "2.0", "2.5", "3.0"}));
  EXPECT_EQ(tickLabels(niceTicks(-1.5, 2.5)), (std::vector<std::string>{"\u22121", "0", "1", "2"}));
  EXPECT_EQ(tickLabels(niceTicks(0, 1)), (std::vector<std::string>{"0", "0.2", "0.4", "0.6", "0.8", "1.0"}));
  EXPECT_EQ(tickLabels(niceTicks(0, 4000)), (std::vector<std::string>{"0", "1000", "2000", "3000", "4000"}));
  // 1e5 and up, and below 1e-3: a mantissa and one common power of ten, never 100000.000000.
  EXPECT_EQ(tickLabels(niceTicks(0, 350000)),
            (std::vector<std::string>{"0", "1\u00d710\u2075", "2\u00d710\u2075", "3\u00d710\u2075"}));
  EXPECT_EQ(tickLabels(niceTicks(1e5, 1.01e5)).front(), "1.000\u00d710\u2075");
  EXPECT_EQ(tickLabels(niceTicks(-4e-4, 0)).front(), "\u22124\u00d710\u207b\u2074");
  EXPECT_EQ(tickLabels(niceTicks(2.5, 2.5)), (std::vector<std::string>{"2.5"}));
}

TEST(LogTicks, DecadesThinnedToAboutTheCountAsked) {
  // Nine decades, about six ticks wanted: every second power of ten, 10^0 among them.
  EXPECT_EQ(logTicks(1e-6, 1e3, 6).values, (std::vector<double>{1e-6, 1e-4, 1e-2, 1, 100}));
  EXPECT_EQ(logTickLabels(logTicks(1e-6, 1e3, 6)),
            (std::vector<std::string>{"10\u207b\u2076", "10\u207b\u2074", "10\u207b\u00b2", "10\u2070",
                                      "10\u00b2"}));
  EXPECT_EQ(logTicks(1, 100).values, (std::vector<double>{1, 10, 100}));
  EXPECT_EQ(logTickLabels(logTicks(1, 100)), (std::vector<std::string>{"1", "10", "100"}));
  EXPECT_EQ(logTickLabels(logTicks(1e-3, 1e5, 6)), (std::vector<std::string>{"0.01", "1", "100", "10000"}));
}

TEST(LogTicks, ShortRangesAddTwoAndFiveTimesAPowerOfTen) {
  EXPECT_EQ(logTicks(3, 40).values, (std::vector<double>{5, 10, 20}));
  EXPECT_EQ(logTicks(0.5, 30).values, (std::vector<double>{0.5, 1, 5, 10}));
  EXPECT_EQ(logTickLabels(logTicks(2e5, 3e6)),
            (std::vector<std::string>{"2\u00d710\u2075", "5\u00d710\u2075", "10\u2076", "2\u00d710\u2076"}));
  // Within one 1-2-5 step: round linear ticks, labelled as a linear legend's.
  EXPECT_EQ(logTicks(3, 4).values, niceTicks(3, 4).values);
  EXPECT_EQ(logTickLabels(logTicks(3, 4)), tickLabels(niceTicks(3, 4)));
}

TEST(Legend, LogBarPlacesDecadeTicksByTheirLogarithm) {
  // 1 .. 100 on a log scale: ticks 1, 10, 100 at the bottom, middle and top of the bar (a linear bar
  // would put 10 at a tenth of its height).
  LegendSpec spec{ColorMapKind::Viridis, 1, 100, "", "", 0};  // no title: only ticks are this grey
  spec.scale = ColorScale::Log;
  const Image image = legendImage(spec, false, 200, 14, false);
  const int tickColumn = 8 + 17 + 2;  // right of the bar: padding 8, bar 17 pixels wide
  std::vector<int> rows;
  for (int y = 0; y < image.height(); ++y) {
    const Rgba& p = image.at(tickColumn, y);
    if (std::abs(p.r - 0.1f) < 1e-3f && std::abs(p.g - 0.1f) < 1e-3f) rows.push_back(y);
  }
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_NEAR(rows[2] - rows[1], rows[1] - rows[0], 1);
  EXPECT_NEAR(rows[2] - rows[0], 199, 1);
  // The bar is the map along log(value): its middle row shows the map's middle.
  const Vec3 middle = image.at(12, rows[1]).rgb();
  EXPECT_LT(length(middle - colorMapLookup(ColorMapKind::Viridis, 0.5f)), 0.02f);
}

TEST(Legend, TitleWithUnits) {
  EXPECT_EQ(legendTitle({ColorMapKind::Viridis, 0, 1, "von Mises stress", "MPa", 0}),
            "von Mises stress (MPa)");
  EXPECT_EQ(legendTitle({ColorMapKind::Viridis, 0, 1, "T", "", 0}), "T");
  EXPECT_EQ(legendTitle({ColorMapKind::Viridis, 0, 1, "", "K", 0}), "(K)");
}

// The distinct bar colours down the column at x of a vertical legend image.
int distinctColoursDown(const Image& image, int x, int y0, int y1) {
  int count = 0;
  Rgba previous{-1, -1, -1, -1};
  for (int y = y0; y < y1; ++y)
    if (!(image.at(x, y) == previous)) {
      previous = image.at(x, y);
      ++count;
    }
  return count;
}

TEST(Legend, BandsMakeADiscreteBarAndTheBarRunsLowToHigh) {
  const LegendSpec continuous{ColorMapKind::Viridis, 0, 10, "T", "K", 0};
  LegendSpec banded = continuous;
  banded.bands = 8;
  const Image smooth = legendImage(continuous, false, 200, 14, false);
  const Image bands = legendImage(banded, false, 200, 14, false);
  ASSERT_EQ(smooth.width(), bands.width());
  ASSERT_EQ(smooth.height(), bands.height());
  // Column 12 crosses the bar (it starts at the padding, 8 pixels, and is 17 wide); rows 40..
  // height-20 lie inside it.
  const int x = 12;
  // The bar from the bottom up (the title above it is apart from it).
  int bottom = bands.height() - 1;
  while (bottom > 0 && bands.at(x, bottom) == Rgba{1, 1, 1, 1}) --bottom;
  int top = bottom;
  while (top > 0 && !(bands.at(x, top - 1) == Rgba{1, 1, 1, 1})) --top;
  EXPECT_EQ(bottom - top + 1, 200);
  EXPECT_EQ(distinctColoursDown(bands, x, top, bottom + 1), 8) << "bar rows " << top << ".." << bottom;
  EXPECT_GT(distinctColoursDown(smooth, x, top, bottom + 1), 100);
  // Low at the bottom, high at the top.
  const Vec3 low = colorMapLookup(ColorMapKind::Viridis, 0.5f / 200),
             high = colorMapLookup(ColorMapKind::Viridis, 1 - 0.5f / 200);
  EXPECT_LT(length(smooth.at(x + 3, bottom).rgb() - low), 0.02f);
  EXPECT_LT(length(smooth.at(x + 3, top).rgb() - high), 0.02f);
}

TEST(Legend, DrawnAtTheRightOrBottomOfThePicture) {
  const LegendSpec spec{ColorMapKind::Magma, 0.5, 3, "temperature", "K", 0};
  const Rgba grey{0.5f, 0.5f, 0.5f, 1};
  auto changedBox = [&](LegendPlacement placement) {
    Image picture(320, 240, grey);
    drawLegends(picture, {&spec, 1}, placement, false);
    int x0 = 320, x1 = 0, y0 = 240, y1 = 0;
    for (int y = 0; y < 240; ++y)
      for (int x = 0; x < 320; ++x)
        if (!(picture.at(x, y) == grey))
          x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    return std::array<int, 4>{x0, y0, x1, y1};
  };
  const auto right = changedBox(LegendPlacement::Right);
  EXPECT_GT(right[0], 160);       // in the right half
  EXPECT_LT(right[1], 120 - 60);  // a bar over half the height, centred
  EXPECT_GT(right[3], 120 + 60);
  EXPECT_LT(right[2], 320);
  const auto bottom = changedBox(LegendPlacement::Bottom);
  EXPECT_GT(bottom[1], 120);  // in the bottom half
  EXPECT_LT(bottom[0], 160 - 60);
  EXPECT_GT(bottom[2], 160 + 60);
  EXPECT_EQ(changedBox(LegendPlacement::None)[0], 320);  // nothing drawn
}

}  // namespace
}  // namespace lancer
