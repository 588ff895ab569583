// The palette quantiser (exact for few colours, Wu's cuts otherwise), nearest-colour search and
// dithering, tested apart from any file format.
#include "lancer/image/palette_quantizer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "lancer/image/dither.hpp"
#include "support/test_images.hpp"

namespace lancer {
namespace {

struct Lcg {
  std::uint32_t state;
  int next(int n) {
    state = state * 1664525u + 1013904223u;
    return static_cast<int>((state >> 8) % static_cast<std::uint32_t>(n));
  }
};

std::vector<std::uint8_t> randomColours(int count, std::uint32_t seed) {
  Lcg lcg{seed};
  std::vector<std::uint8_t> rgb;
  for (int i = 0; i < 3 * count; ++i) rgb.push_back(static_cast<std::uint8_t>(lcg.next(256)));
  return rgb;
}

// Every pixel replaced by its palette colour.
std::vector<std::uint8_t> reproduce(const std::vector<std::uint8_t>& rgb, int width, int height,
                                    const Palette& palette, Dither dither = Dither::None) {
  NearestColour nearest(palette);
  std::vector<std::uint8_t> indices(rgb.size() / 3);
  mapToPalette(rgb, width, height, nearest, dither, indices);
  std::vector<std::uint8_t> out;
  for (std::uint8_t i : indices) {
    out.push_back(palette[i].r);
    out.push_back(palette[i].g);
    out.push_back(palette[i].b);
  }
  return out;
}

// A smooth 256x64 gradient over all three channels: 16384 distinct colours.
std::vector<std::uint8_t> gradient(int width, int height) {
  std::vector<std::uint8_t> rgb;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      rgb.push_back(static_cast<std::uint8_t>(x * 255 / (width - 1)));
      rgb.push_back(static_cast<std::uint8_t>(y * 255 / (height - 1)));
      rgb.push_back(static_cast<std::uint8_t>(128 + (x - y) / 4));
    }
  }
  return rgb;
}

TEST(PaletteQuantizer, ImageWithAtMost256ColoursIsReproducedExactly) {
  for (int count : {1, 2, 200, 256}) {
    SCOPED_TRACE(count);
    // Each colour repeated and shuffled over a 64-pixel-wide image, with near-identical neighbours
    // (differing by one unit) that a 5-bit histogram alone could not tell apart.
    std::vector<std::uint8_t> colours = randomColours(count, 7);
    if (count >= 2)
      colours[3] = colours[0], colours[4] = colours[1],
      colours[5] = static_cast<std::uint8_t>(colours[2] ^ 1);
    std::vector<std::uint8_t> rgb;
    Lcg lcg{99};
    for (int i = 0; i < 64 * 16; ++i) {
      const int c = lcg.next(count);
      rgb.insert(rgb.end(), colours.begin() + 3 * c, colours.begin() + 3 * c + 3);
    }
    const Palette palette = quantize(rgb);
    std::set<std::uint32_t> distinct;
    for (std::size_t i = 0; i < rgb.size(); i += 3)
      distinct.insert((rgb[i] << 16) | (rgb[i + 1] << 8) | rgb[i + 2]);
    EXPECT_EQ(palette.size(), distinct.size());
    PaletteBuilder builder;
    builder.add(rgb);
    EXPECT_TRUE(builder.exact());
    EXPECT_EQ(reproduce(rgb, 64, 16, palette), rgb);
  }
}

TEST(PaletteQuantizer, SmoothGradientHasSmallMeanError) {
  const std::vector<std::uint8_t> rgb = gradient(256, 64);
  PaletteBuilder builder;
  builder.add(rgb);
  EXPECT_FALSE(builder.exact());
  const Palette palette = builder.build();
  EXPECT_LE(palette.size(), 256u);
  EXPECT_GE(palette.size(), 200u);  // Wu's cuts use (nearly) the whole budget
  const test::SampleError error = test::sampleError(reproduce(rgb, 256, 64, palette), rgb);
  RecordProperty("mean_error", std::to_string(error.mean));
  // 256 boxes tile the gradient's 256 x 256 (r, g) plane in about 16 x 16 squares: a mean error of
  // about 4 on r and g and near 0 on b, so about 2.7 per sample is the best any palette can do.
  EXPECT_LT(error.mean, 3.5) << "max " << error.max;
  EXPECT_LE(error.max, 12);
}

TEST(PaletteQuantizer, RandomColoursBeatAUniformPalette) {
  // Uniform noise is the worst case: no palette does much better than a uniform 6x7x6 grid, whose
  // cells are about 40 wide, for a mean error of about 40 / 4 = 10.
  const std::vector<std::uint8_t> rgb = randomColours(128 * 128, 3);
  const Palette palette = quantize(rgb);
  EXPECT_EQ(palette.size(), 256u);
  const test::SampleError error = test::sampleError(reproduce(rgb, 128, 128, palette), rgb);
  EXPECT_LT(error.mean, 11.0);
}

TEST(PaletteQuantizer, SmallerBudgetsAreRespected) {
  const std::vector<std::uint8_t> rgb = gradient(256, 64);
  for (int colours : {1, 2, 16, 100}) {
    PaletteBuilder builder(colours);
    builder.add(rgb);
    EXPECT_LE(builder.build().size(), static_cast<std::size_t>(colours));
    EXPECT_GE(builder.build().size(), 1u);
  }
  EXPECT_THROW(PaletteBuilder(0), std::invalid_argument);
  EXPECT_THROW(PaletteBuilder(257), std::invalid_argument);
}

TEST(PaletteQuantizer, StatisticsAccumulateOverSeveralImages) {
  // Two halves added separately give the palette of the whole.
  const std::vector<std::uint8_t> rgb = gradient(256, 64);
  const std::size_t half = rgb.size() / 2;
  PaletteBuilder builder;
  builder.add(std::span<const std::uint8_t>(rgb).first(half));
  builder.add(std::span<const std::uint8_t>(rgb).subspan(half));
  EXPECT_EQ(builder.build(), quantize(rgb));
}

TEST(NearestColour, EqualsBruteForceIncludingTies) {
  Palette palette;
  const std::vector<std::uint8_t> colours = randomColours(256, 11);
  for (std::size_t i = 0; i < colours.size(); i += 3)
    palette.push_back({colours[i], colours[i + 1], colours[i + 2]});
  palette[17] = palette[200];  // a duplicate: the lower index wins
  NearestColour nearest(palette);
  Lcg lcg{5};
  for (int q = 0; q < 20000; ++q) {
    const int r = lcg.next(256), g = lcg.next(256), b = lcg.next(256);
    int best = 0, bestDistance = 1 << 30;
    for (int i = 0; i < 256; ++i) {
      const Rgb8& c = palette[static_cast<std::size_t>(i)];
      const int d = (c.r - r) * (c.r - r) + (c.g - g) * (c.g - g) + (c.b - b) * (c.b - b);
      if (d < bestDistance) best = i, bestDistance = d;
    }
    ASSERT_EQ(nearest(r, g, b), best) << r << "," << g << "," << b;
    ASSERT_EQ(nearest(r, g, b), best) << "cached answer";
  }
  EXPECT_EQ(nearest(palette[200].r, palette[200].g, palette[200].b), 17);
}

// With only black and white, a dithered grey ramp keeps its local average brightness.
TEST(Dither, TwoColourRampKeepsLocalAverages) {
  constexpr int kWidth = 64, kHeight = 64;
  std::vector<std::uint8_t> rgb;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 3; ++c) rgb.push_back(static_cast<std::uint8_t>(x * 4 + 2));
  const Palette blackWhite = {{0, 0, 0}, {255, 255, 255}};
  for (Dither dither : {Dither::Ordered, Dither::FloydSteinberg}) {
    const std::vector<std::uint8_t> out = reproduce(rgb, kWidth, kHeight, blackWhite, dither);
    for (int x0 = 0; x0 < kWidth; x0 += 8) {
      double sum = 0, want = 0;
      for (int y = 0; y < kHeight; ++y)
        for (int x = x0; x < x0 + 8; ++x) {
          sum += out[3 * static_cast<std::size_t>(y * kWidth + x)];
          want += rgb[3 * static_cast<std::size_t>(y * kWidth + x)];
        }
      EXPECT_NEAR(sum / (8 * kHeight), want / (8 * kHeight), 12.0)
          << "columns " << x0 << ".. with " << (dither == Dither::Ordered ? "ordered" : "Floyd-Steinberg");
    }
  }
  // Without dithering, each pixel just snaps to the nearer of black and white.
  const std::vector<std::uint8_t> plain = reproduce(rgb, kWidth, kHeight, blackWhite);
  EXPECT_EQ(plain[0], 0);
  EXPECT_EQ(plain[3 * (kWidth - 1)], 255);
}

TEST(Dither, ExactPaletteStaysExactWithErrorDiffusion) {
  std::vector<std::uint8_t> rgb = randomColours(50, 21);
  rgb.insert(rgb.end(), rgb.begin(), rgb.end());  // 100 pixels, 50 colours
  const Palette palette = quantize(rgb);
  EXPECT_EQ(reproduce(rgb, 10, 10, palette, Dither::FloydSteinberg), rgb);
}

}  // namespace
}  // namespace lancer
