// Image storage, tiles, and the 8-bit encodings (linear and sRGB).
#include "lancer/image/image.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>
#include <vector>

#include "lancer/image/pixel_encoding.hpp"

namespace lancer {
namespace {

TEST(Image, StartsFilledAndOpaque) {
  Image image(3, 2);
  EXPECT_EQ(image.width(), 3);
  EXPECT_EQ(image.height(), 2);
  EXPECT_EQ(image.pixels().size(), 6u);
  for (const Rgba& p : image.pixels()) EXPECT_EQ(p, (Rgba{0, 0, 0, 1}));
  EXPECT_FALSE(image.hasTransparency());
  EXPECT_TRUE(Image().empty());
}

TEST(Image, PixelsAreRowMajorFromTheTop) {
  Image image(3, 2);
  image.setRgb(2, 1, Vec3{0.25f, 0.5f, 0.75f}, 0.5f);
  EXPECT_EQ(image.pixels()[5], (Rgba{0.25f, 0.5f, 0.75f, 0.5f}));
  EXPECT_EQ(image.row(1)[2].rgb(), (Vec3{0.25f, 0.5f, 0.75f}));
  EXPECT_EQ(image.row(1).size(), 3u);
}

TEST(Image, RejectsSizesOutsideTheLimit) {
  EXPECT_THROW(Image(-1, 3), std::invalid_argument);
  EXPECT_THROW(Image(kMaxImageSide + 1, 1), std::invalid_argument);
  EXPECT_NO_THROW(Image(0, 0));
}

TEST(Image, TransparencyMeansAnAlphaBelow255WhenEncoded) {
  Image image(2, 2);
  image.at(1, 1).a = 0.999f;  // encodes to 255
  EXPECT_FALSE(image.hasTransparency());
  image.at(1, 1).a = 0.99f;  // encodes to 252
  EXPECT_TRUE(image.hasTransparency());
}

TEST(Image, TilesPastedFromSeveralThreadsGiveTheSequentialImage) {
  constexpr int kWidth = 37, kHeight = 29, kTile = 8;
  auto colourAt = [](int x, int y) { return Rgba{x * 0.01f, y * 0.02f, (x + y) * 0.005f, 1}; };
  Image expected(kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) expected.at(x, y) = colourAt(x, y);

  Image image(kWidth, kHeight);
  std::vector<std::thread> workers;
  for (int t = 0; t < 4; ++t) {
    workers.emplace_back([&, t] {
      int tileIndex = 0;
      for (int y0 = 0; y0 < kHeight; y0 += kTile) {
        for (int x0 = 0; x0 < kWidth; x0 += kTile, ++tileIndex) {
          if (tileIndex % 4 != t) continue;
          Image tile(std::min(kTile, kWidth - x0), std::min(kTile, kHeight - y0));
          for (int y = 0; y < tile.height(); ++y)
            for (int x = 0; x < tile.width(); ++x) tile.at(x, y) = colourAt(x0 + x, y0 + y);
          image.pasteTile(tile, x0, y0);
        }
      }
    });
  }
  for (std::thread& worker : workers) worker.join();
  EXPECT_EQ(image, expected);
  EXPECT_EQ(image.crop(8, 16, 8, 8), expected.crop(8, 16, 8, 8));
  EXPECT_EQ(image.crop(3, 4, 5, 6).at(0, 0), colourAt(3, 4));
}

TEST(Image, TilesAndCropsMustLieInside) {
  Image image(4, 4);
  EXPECT_THROW(image.pasteTile(Image(2, 2), 3, 0), std::invalid_argument);
  EXPECT_THROW(image.pasteTile(Image(2, 2), -1, 0), std::invalid_argument);
  EXPECT_THROW(static_cast<void>(image.crop(2, 2, 3, 1)), std::invalid_argument);
}

TEST(PixelEncoding, LinearIsRound255TimesClamped) {
  EXPECT_EQ(encode8(0.0f), 0);
  EXPECT_EQ(encode8(1.0f), 255);
  EXPECT_EQ(encode8(0.5f), 128);  // 127.5 rounds up
  EXPECT_EQ(encode8(0.4f), 102);  // 102.0
  EXPECT_EQ(encode8(1.0f / 255.0f), 1);
  EXPECT_EQ(encode8(0.49f / 255.0f), 0);
  EXPECT_EQ(encode8(-3.0f), 0);
  EXPECT_EQ(encode8(7.0f), 255);
  EXPECT_EQ(encode8(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(encode8(std::numeric_limits<float>::infinity()), 255);
  EXPECT_EQ(encode8(-std::numeric_limits<float>::infinity()), 0);
}

TEST(PixelEncoding, SrgbCurveMatchesTheStandard) {
  // IEC 61966-2-1: the two pieces meet at linear 0.0031308 / encoded 0.04045.
  EXPECT_NEAR(srgbFromLinear(0.0031308f), 0.04045f, 1e-5f);
  EXPECT_NEAR(srgbFromLinear(0.5f), 0.735357f, 1e-5f);
  EXPECT_NEAR(srgbFromLinear(0.18f), 0.461356f, 1e-5f);  // photographic mid-grey
  EXPECT_NEAR(linearFromSrgb(0.5f), 0.214041f, 1e-5f);
  EXPECT_FLOAT_EQ(srgbFromLinear(1.0f), 1.0f);
  EXPECT_FLOAT_EQ(srgbFromLinear(0.0f), 0.0f);
  EXPECT_EQ(encode8(0.5f, TransferCurve::Srgb), 188);
  EXPECT_EQ(encode8(0.001f, TransferCurve::Srgb), 3);  // linear piece: 255 * 12.92 * 0.001 = 3.29
  EXPECT_EQ(encode8(0.2158605f, TransferCurve::Srgb), 128);
}

TEST(PixelEncoding, DecodingThenEncodingGivesBackEveryByte) {
  for (int v = 0; v < 256; ++v) {
    const auto byte = static_cast<std::uint8_t>(v);
    EXPECT_EQ(encode8(decode8(byte)), byte);
    EXPECT_EQ(encode8(decode8(byte, TransferCurve::Srgb), TransferCurve::Srgb), byte);
  }
}

TEST(PixelEncoding, SrgbIsMonotonicAndBrighterThanLinear) {
  int previous = 0;
  for (int i = 0; i <= 1000; ++i) {
    const float v = static_cast<float>(i) / 1000.0f;
    const int encoded = encode8(v, TransferCurve::Srgb);
    EXPECT_GE(encoded, previous);
    EXPECT_GE(encoded, encode8(v));
    previous = encoded;
  }
}

TEST(PixelEncoding, RowsEncodeAsInterleavedSamplesWithAlphaAlwaysLinear) {
  const std::vector<Rgba> row = {{1, 0, 0.5f, 0.5f}, {0.2f, 0.4f, 0.6f, 1}};
  std::uint8_t rgb[6], rgba[8];
  encodeRow8(row, TransferCurve::Linear, 3, rgb);
  EXPECT_EQ(std::vector<int>(rgb, rgb + 6), (std::vector<int>{255, 0, 128, 51, 102, 153}));
  encodeRow8(row, TransferCurve::Srgb, 4, rgba);
  EXPECT_EQ(std::vector<int>(rgba, rgba + 8), (std::vector<int>{255, 0, 188, 128, 124, 170, 203, 255}));
}

}  // namespace
}  // namespace lancer
