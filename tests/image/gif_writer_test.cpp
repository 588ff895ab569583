// Animated GIFs decoded independently: with giflib's DGif* API always, and with Pillow or
// ImageMagick when they are installed (skipped otherwise).
#include "lancer/image/gif_writer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "support/cli.hpp"
#include "support/files.hpp"
#include "support/gif_decoder.hpp"
#include "support/test_images.hpp"

namespace lancer {
namespace {

using test::DecodedGif;
using test::decodeGif;
using test::ScratchFolder;

// Frames with few colours: a square moving over a two-colour background.
Image flatFrame(int k) {
  Image image(40, 30, Rgba{0.1f, 0.2f, 0.6f, 1});
  for (int y = 0; y < 15; ++y) image.row(y)[0] = {1, 1, 1, 1};
  for (int y = 10; y < 20; ++y)
    for (int x = 5 + 6 * k; x < 13 + 6 * k; ++x) image.at(x, y) = {1, 0.5f, 0, 1};
  return image;
}

std::vector<std::uint8_t> rgb8(const Image& image) { return encodeImage8(image, TransferCurve::Linear, 3); }

DecodedGif writeAndDecode(const std::string& path, const std::vector<Image>& frames,
                          const GifOptions& options) {
  GifWriter writer(path, frames[0].width(), frames[0].height(), options);
  for (const Image& frame : frames) writer.addFrame(frame);
  EXPECT_EQ(writer.frameCount(), static_cast<int>(frames.size()));
  writer.finish();
  return decodeGif(path);
}

TEST(GifFrameDelay, IsHundredthsRoundedAndNeverBelowTwo) {
  EXPECT_EQ(gifFrameDelay(10), 10);
  EXPECT_EQ(gifFrameDelay(12), 8);  // 8.33
  EXPECT_EQ(gifFrameDelay(25), 4);
  EXPECT_EQ(gifFrameDelay(30), 3);  // 3.33
  EXPECT_EQ(gifFrameDelay(50), 2);
  EXPECT_EQ(gifFrameDelay(60), 2);  // 1.67 would be slowed down by viewers
  EXPECT_EQ(gifFrameDelay(1000), 2);
  EXPECT_EQ(gifFrameDelay(0.5), 200);
  EXPECT_EQ(gifFrameDelay(0.001), 65535);
}

TEST(GifFrameDelay, ActualFrameRateIsWhatTheDelayGives) {
  EXPECT_DOUBLE_EQ(gifActualFrameRate(10), 10.0);
  EXPECT_DOUBLE_EQ(gifActualFrameRate(12), 12.5);
  EXPECT_NEAR(gifActualFrameRate(30), 33.333, 1e-3);
  EXPECT_DOUBLE_EQ(gifActualFrameRate(60), 50.0);
  EXPECT_DOUBLE_EQ(gifActualFrameRate(20), 20.0);
}

TEST(GifWriter, FewColourAnimationDecodesExactly) {
  ScratchFolder folder;
  std::vector<Image> frames;
  for (int k = 0; k < 4; ++k) frames.push_back(flatFrame(k));
  GifOptions options;
  options.fps = 25;
  const DecodedGif gif = writeAndDecode(folder.file("a.gif"), frames, options);
  ASSERT_NO_FATAL_FAILURE(
      test::expectGifLayout(gif, {.width = 40, .height = 30, .loopCount = 0, .frames = 4, .delay = 4}));
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(gif.frames[k].canvas, rgb8(frames[k])) << "frame " << k;
  // After the first, frames store only the rectangle that changed: the square's old and new place.
  EXPECT_EQ(gif.frames[0].width, 40);
  EXPECT_EQ(gif.frames[1].left, 5);
  EXPECT_EQ(gif.frames[1].top, 10);
  EXPECT_EQ(gif.frames[1].width, 14);
  EXPECT_EQ(gif.frames[1].height, 10);
}

TEST(GifWriter, FramesThatFitThePaletteAreNeverDithered) {
  ScratchFolder folder;
  for (Dither dither : {Dither::Ordered, Dither::FloydSteinberg}) {
    for (GifPalette palette : {GifPalette::Global, GifPalette::PerFrame}) {
      GifOptions options;
      options.dither = dither;
      options.palette = palette;
      const DecodedGif gif = writeAndDecode(folder.file("a.gif"), {flatFrame(0), flatFrame(3)}, options);
      ASSERT_EQ(gif.frames.size(), 2u);
      EXPECT_EQ(gif.frames[0].canvas, rgb8(flatFrame(0)));
      EXPECT_EQ(gif.frames[1].canvas, rgb8(flatFrame(3)));
    }
  }
}

TEST(GifWriter, UnchangedFrameIsStoredAsOnePixel) {
  ScratchFolder folder;
  const DecodedGif gif = writeAndDecode(folder.file("a.gif"), {flatFrame(0), flatFrame(0)}, {});
  ASSERT_EQ(gif.frames.size(), 2u);
  EXPECT_EQ(gif.frames[1].width * gif.frames[1].height, 1);
  EXPECT_EQ(gif.frames[1].canvas, rgb8(flatFrame(0)));
  EXPECT_EQ(gif.frames[1].delay, 10);
}

TEST(GifWriter, LoopCountIsWrittenOrLeftOut) {
  ScratchFolder folder;
  GifOptions options;
  options.loopCount = 3;
  EXPECT_EQ(writeAndDecode(folder.file("three.gif"), {flatFrame(0), flatFrame(1)}, options).loopCount, 3);
  options.loopCount = 65535;
  EXPECT_EQ(writeAndDecode(folder.file("many.gif"), {flatFrame(0), flatFrame(1)}, options).loopCount, 65535);
  options.loopCount = kGifPlayOnce;
  EXPECT_FALSE(
      writeAndDecode(folder.file("once.gif"), {flatFrame(0), flatFrame(1)}, options).loopCount.has_value());
}

TEST(GifWriter, SmoothShadingIsWithinQuantisationTolerance) {
  ScratchFolder folder;
  std::vector<Image> frames;
  for (int k = 0; k < 3; ++k) frames.push_back(test::shadedSphere(96, 64, static_cast<float>(k) / 3.0f));
  for (Dither dither : {Dither::None, Dither::Ordered, Dither::FloydSteinberg}) {
    for (GifPalette palette : {GifPalette::Global, GifPalette::PerFrame}) {
      SCOPED_TRACE(testing::Message()
                   << "dither " << static_cast<int>(dither) << ", palette " << static_cast<int>(palette));
      GifOptions options;
      options.fps = 12;
      options.dither = dither;
      options.palette = palette;
      const DecodedGif gif = writeAndDecode(folder.file("s.gif"), frames, options);
      ASSERT_EQ(gif.error, "");
      ASSERT_EQ(gif.frames.size(), 3u);
      EXPECT_EQ(gif.globalPalette, palette == GifPalette::Global);
      for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(gif.frames[k].delay, 8);
        EXPECT_EQ(gif.frames[k].localPalette, palette == GifPalette::PerFrame);
        const test::SampleError error = test::sampleError(gif.frames[k].canvas, rgb8(frames[k]));
        EXPECT_LT(error.mean, dither == Dither::None ? 1.5 : 3.0) << "frame " << k;
        EXPECT_LE(error.max, dither == Dither::None ? 8 : 24) << "frame " << k;
      }
    }
  }
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"s.gif"});
}

// Banding is error at low spatial frequency: contours where a smooth ramp steps from one palette
// colour to the next. Averaged over any 8x8 block, dithered output must follow the true colours
// closely, where plain nearest-colour mapping cannot.
double worstBlockAverageError(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                              int width, int height) {
  double worst = 0;
  // Blocks at the border are left out: palette entries are means of their colours, so the ramp's
  // extreme values lie outside the palette's hull, where no dithering can reach them.
  for (int by = 16; by + 8 <= height - 16; by += 8) {
    for (int bx = 16; bx + 8 <= width - 16; bx += 8) {
      for (std::size_t c = 0; c < 3; ++c) {
        double da = 0, db = 0;
        for (int y = by; y < by + 8; ++y)
          for (int x = bx; x < bx + 8; ++x) {
            const std::size_t i = 3 * static_cast<std::size_t>(y * width + x) + c;
            da += a[i];
            db += b[i];
          }
        worst = std::max(worst, std::abs(da - db) / 64);
      }
    }
  }
  return worst;
}

TEST(GifWriter, DitheringRemovesBandingFromSmoothRamps) {
  // A ramp over red, green and blue together: 192 x 128 pixels, far more colours than 256.
  Image ramp(192, 128);
  for (int y = 0; y < ramp.height(); ++y)
    for (int x = 0; x < ramp.width(); ++x)
      ramp.at(x, y) = {x / 191.0f, y / 127.0f, 0.5f + 0.3f * (x - y) / 192.0f, 1};
  ScratchFolder folder;
  const std::vector<std::uint8_t> truth = rgb8(ramp);
  std::vector<double> errors;
  for (Dither dither : {Dither::None, Dither::Ordered, Dither::FloydSteinberg}) {
    GifOptions options;
    options.dither = dither;
    const DecodedGif gif = writeAndDecode(folder.file("r.gif"), {ramp}, options);
    ASSERT_EQ(gif.frames.size(), 1u);
    errors.push_back(worstBlockAverageError(gif.frames[0].canvas, truth, ramp.width(), ramp.height()));
  }
  RecordProperty("block_error_none_ordered_fs",
                 fmt::format("{:.2f} {:.2f} {:.2f}", errors[0], errors[1], errors[2]));
  // Measured: 3.0 without dithering (steps of 3/255 between bands), 1.14 ordered, 0.62 Floyd-Steinberg.
  EXPECT_GT(errors[0], 2.0);  // the bands are there without dithering...
  EXPECT_LT(errors[1], 1.5);  // ...and smoothed out with it
  EXPECT_LT(errors[2], 1.0);
}

TEST(GifWriter, SrgbCurveEncodesFramesWithIt) {
  ScratchFolder folder;
  GifOptions options;
  options.curve = TransferCurve::Srgb;
  const DecodedGif gif = writeAndDecode(folder.file("s.gif"), {flatFrame(0)}, options);
  ASSERT_EQ(gif.frames.size(), 1u);
  EXPECT_EQ(gif.frames[0].canvas, encodeImage8(flatFrame(0), TransferCurve::Srgb, 3));
}

TEST(GifWriter, MisuseIsALogicError) {
  ScratchFolder folder;
  GifWriter writer(folder.file("a.gif"), 40, 30);
  EXPECT_THROW(writer.addFrame(Image(30, 40)), std::invalid_argument);
  EXPECT_THROW(writer.finish(), std::logic_error);  // no frames
  writer.addFrame(flatFrame(0));
  writer.finish();
  EXPECT_THROW(writer.finish(), std::logic_error);
  EXPECT_THROW(writer.addFrame(flatFrame(0)), std::logic_error);
  EXPECT_EQ(decodeGif(folder.file("a.gif")).frames.size(), 1u);
}

// Runs a command, returning its standard output; nullopt when it fails.
std::optional<std::string> run(const std::string& command) {
  const test::CommandResult result = test::runShell(command);
  return result.exitCode == 0 ? std::optional(result.output) : std::nullopt;
}

void writeTestAnimation(const std::string& path) {
  GifOptions options;
  options.fps = 20;
  options.loopCount = 2;
  GifWriter writer(path, 40, 30, options);
  for (int k = 0; k < 3; ++k) writer.addFrame(flatFrame(k));
  writer.finish();
}

TEST(GifWriterIndependentDecoders, Pillow) {
  const std::optional<std::string> python = test::pythonWithPillow();
  if (!python) GTEST_SKIP() << "no python3 with PIL (Debian: python3-pil)";
  ScratchFolder folder;
  writeTestAnimation(folder.file("a.gif"));
  std::FILE* script = std::fopen(folder.file("decode.py").c_str(), "w");
  ASSERT_NE(script, nullptr);
  std::fputs(
      "import sys\n"
      "from PIL import Image, ImageSequence\n"
      "im = Image.open(sys.argv[1])\n"
      "print(im.size[0], im.size[1], im.n_frames, im.info.get('loop'))\n"
      "for f in ImageSequence.Iterator(im):\n"
      "    rgb = f.convert('RGB')\n"
      "    print(f.info.get('duration'), *rgb.getpixel((8, 12)), *rgb.getpixel((20, 12)), *rgb.getpixel((0, "
      "25)))\n",
      script);
  std::fclose(script);
  const std::optional<std::string> out =
      run(*python + " " + folder.file("decode.py") + " " + folder.file("a.gif"));
  ASSERT_TRUE(out.has_value());
  // Durations in milliseconds; the square (x from 5 + 6k to 12 + 6k) covers (8, 12) in frame 0 only and
  // (20, 12) in frame 2 only.
  EXPECT_EQ(*out,
            "40 30 3 2\n"
            "50 255 128 0 26 51 153 26 51 153\n"
            "50 26 51 153 26 51 153 26 51 153\n"
            "50 26 51 153 255 128 0 26 51 153\n");
}

TEST(GifWriterIndependentDecoders, ImageMagick) {
  if (!test::imageMagickInstalled()) GTEST_SKIP() << "ImageMagick not installed";
  ScratchFolder folder;
  writeTestAnimation(folder.file("a.gif"));
  const std::optional<std::string> out = run("identify -format '%W %H %T %n|' " + folder.file("a.gif"));
  ASSERT_TRUE(out.has_value());
  EXPECT_EQ(*out, "40 30 5 3|40 30 5 3|40 30 5 3|");  // canvas, delay in hundredths, frame count
  // ImageMagick reports the number of plays: the NETSCAPE repeat count 2 plus the first showing.
  const std::optional<std::string> iterations =
      run("identify -verbose " + folder.file("a.gif") + "[0] | grep -m1 'Iterations:'");
  ASSERT_TRUE(iterations.has_value());
  EXPECT_EQ(*iterations, "  Iterations: 3\n");
  // Pixels: the coalesced frames, as raw RGB.
  const std::optional<std::string> pixels = run("convert " + folder.file("a.gif") + " -coalesce rgb:-");
  ASSERT_TRUE(pixels.has_value());
  std::vector<std::uint8_t> expected;
  for (int k = 0; k < 3; ++k) {
    const std::vector<std::uint8_t> frame = rgb8(flatFrame(k));
    expected.insert(expected.end(), frame.begin(), frame.end());
  }
  EXPECT_EQ(std::vector<std::uint8_t>(pixels->begin(), pixels->end()), expected);
}

}  // namespace
}  // namespace lancer
