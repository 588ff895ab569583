// Publishable output: the tone curves against their published formulas, 16-bit PNG and OpenEXR
// written and read back, and the bit-depth and format checks with their messages.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "lancer/image/exr_io.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/image/tone_map.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

Image ramp(int width = 37, int height = 5) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      image.at(x, y) = {static_cast<float>(x) / static_cast<float>(width - 1), 0.25f * static_cast<float>(y),
                        0.5f, 1.0f};
  return image;
}

TEST(ToneMap, AcesIsNarkowiczsFit) {
  for (const double x : {0.0, 0.1, 0.5, 1.0, 4.0, 100.0}) {
    const double v = 0.6 * x;  // his pre-exposure
    const double expected = std::min(1.0, v * (2.51 * v + 0.03) / (v * (2.43 * v + 0.59) + 0.14));
    EXPECT_NEAR(acesCurve(static_cast<float>(x)), expected, 1e-6) << x;
  }
}

TEST(ToneMap, FilmicIsHablesCurveScaledToItsWhitePoint) {
  const auto f = [](double x) {
    return (x * (0.15 * x + 0.05) + 0.004) / (x * (0.15 * x + 0.5) + 0.06) - 0.02 / 0.3;
  };
  for (const double x : {0.0, 0.1, 0.5, 1.0, 5.6})
    EXPECT_NEAR(filmicCurve(static_cast<float>(x)), f(2 * x) / f(11.2), 1e-6) << x;
  EXPECT_NEAR(filmicCurve(5.6f), 1.0f, 1e-6f);  // the white point, after the exposure bias of 2
}

TEST(ToneMap, CurvesRiseFromZeroTowardsOne) {
  float lastAces = -1, lastFilmic = -1;
  for (float x = 0; x < 50; x += 0.25f) {
    EXPECT_GT(acesCurve(x), lastAces - 1e-7f);
    EXPECT_GT(filmicCurve(x), lastFilmic - 1e-7f);
    lastAces = acesCurve(x);
    lastFilmic = filmicCurve(x);
  }
  EXPECT_EQ(acesCurve(0), 0.0f);
  EXPECT_NEAR(filmicCurve(0), 0.0f, 1e-7f);
  EXPECT_GT(acesCurve(50), 0.99f);
}

TEST(ToneMap, NoCurveAndNoExposureChangeNothing) {
  Image image = ramp();
  image.at(3, 2).r = 7.5f;
  const Image before = image;
  applyToneMap(image, ToneMap::None, 0.0f);
  EXPECT_EQ(image, before);
  applyToneMap(image, ToneMap::None, 1.0f);  // one stop: twice the radiance
  EXPECT_EQ(image.at(3, 2).r, 15.0f);
  EXPECT_EQ(image.at(3, 2).a, 1.0f);
}

TEST(Png16, RoundTripsSixteenBitSamples) {
  const test::ScratchFolder folder;
  ImageWriteOptions options;
  options.bitDepth = 16;
  for (const TransferCurve curve : {TransferCurve::Linear, TransferCurve::Srgb}) {
    options.curve = curve;
    writeImage(folder.file("a.png"), ramp(), options);
    const Image back = readPng16(folder.file("a.png"), curve);
    for (int y = 0; y < 5; ++y)
      for (int x = 0; x < 37; ++x) {
        EXPECT_NEAR(back.at(x, y).r, std::min(1.0f, ramp().at(x, y).r), 1e-4f);
        EXPECT_NEAR(back.at(x, y).g, std::min(1.0f, ramp().at(x, y).g), 1e-4f);
      }
    // The 8-bit reader sees the same picture to within a step.
    EXPECT_NEAR(readPng(folder.file("a.png"), curve).at(20, 1).r, ramp().at(20, 1).r, 1.0f / 255);
  }
  EXPECT_EQ(encode16(0.5f), 32768);
  EXPECT_EQ(encode16(2.0f), 65535);
}

TEST(Png16, OtherFormatsRefuseSixteenBits) {
  const test::ScratchFolder folder;
  ImageWriteOptions options;
  options.bitDepth = 16;
  EXPECT_EQ(
      test::messageOf([&] { writeImage(folder.file("a.bmp"), ramp(), options); }),
      folder.file("a.bmp") +
          ": error: 16-bit samples are written to PNG only: give -o NAME.png, or leave --bit-depth at 8");
  options.bitDepth = 12;
  EXPECT_EQ(test::messageOf([&] { writeImage(folder.file("a.png"), ramp(), options); }),
            folder.file("a.png") + ": error: bit depth 12 is not supported: use 8 or 16");
  EXPECT_TRUE(folder.entries().empty());
}

TEST(Exr, RoundTripsRadianceAndLayers) {
  if (!exrSupported()) GTEST_SKIP() << "built without OpenEXR";
  const test::ScratchFolder folder;
  Image image = ramp();
  image.at(0, 0) = {12.5f, -0.25f, 1e-6f, 0.5f};  // HDR, negative and tiny values survive
  ExrLayers layers;
  const std::size_t n = 37 * 5;
  for (std::size_t i = 0; i < n; ++i) {
    layers.albedo.push_back({0.1f * static_cast<float>(i % 7), 0.5f, 1.0f});
    layers.normal.push_back({0, 0, i % 2 == 0 ? 1.0f : -1.0f});
    layers.depth.push_back(i % 5 == 0 ? std::numeric_limits<float>::infinity()
                                      : static_cast<float>(i) * 0.5f);
  }
  writeExr(folder.file("a.exr"), image, layers);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"a.exr"});  // no temporary file left
  ExrLayers back;
  EXPECT_EQ(readExr(folder.file("a.exr"), &back), image);
  EXPECT_EQ(back.albedo, layers.albedo);
  EXPECT_EQ(back.normal, layers.normal);
  EXPECT_EQ(back.depth, layers.depth);
  // Without layers the file holds R, G, B, A alone; writeImage takes the radiance, unclamped.
  writeImage(folder.file("b.exr"), image);
  EXPECT_EQ(readExr(folder.file("b.exr"), &back), image);
  EXPECT_TRUE(back.albedo.empty() && back.normal.empty() && back.depth.empty());
}

TEST(Exr, BadPathsAndFilesAreInputErrors) {
  if (!exrSupported()) GTEST_SKIP() << "built without OpenEXR";
  const test::ScratchFolder folder;
  EXPECT_EQ(test::messageOf([&] { writeExr(folder.file("none/a.exr"), ramp()); }),
            folder.file("none/a.exr") + ": error: cannot write here: the folder '" + folder.file("none") +
                "' does not exist");
  folder.write("bad.exr", "not an exr");
  EXPECT_NE(test::messageOf([&] { readExr(folder.file("bad.exr")); }).find("bad.exr: error: unreadable EXR"),
            std::string::npos);
}

}  // namespace
}  // namespace lancer
