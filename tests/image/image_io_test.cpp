// PNG / BMP / PPM / single-frame GIF output and PNG input: round trips and byte layouts.
#include "lancer/image/image_io.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/files.hpp"
#include "support/gif_decoder.hpp"

namespace lancer {
namespace {

using test::readBytes;
using test::ScratchFolder;

// A 7x5 image with distinct, non-grid values in every channel.
Image testPattern(bool transparent = false) {
  Image image(7, 5);
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      image.at(x, y) = {x / 6.0f, y / 4.0f, 0.1f + 0.013f * static_cast<float>(x * y),
                        transparent ? static_cast<float>(x + y) / 10.0f : 1.0f};
    }
  }
  image.at(0, 0) = {-1, 2, 0.5f, 1};  // out-of-range values clamp
  return image;
}

std::uint32_t be32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) | (std::uint32_t{b[at + 2]} << 8) |
         b[at + 3];
}
std::uint32_t le32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return std::uint32_t{b[at]} | (std::uint32_t{b[at + 1]} << 8) | (std::uint32_t{b[at + 2]} << 16) |
         (std::uint32_t{b[at + 3]} << 24);
}
std::uint32_t le16(const std::vector<std::uint8_t>& b, std::size_t at) { return b[at] | (b[at + 1] << 8); }

// The PNG IHDR colour type: 2 = RGB, 6 = RGBA.
int pngColourType(const std::string& path) { return readBytes(path).at(25); }

bool hasPngChunk(const std::string& path, const std::string& type) {
  const std::vector<std::uint8_t> bytes = readBytes(path);
  for (std::size_t at = 8; at + 8 <= bytes.size();) {
    if (std::string(bytes.begin() + static_cast<std::ptrdiff_t>(at + 4),
                    bytes.begin() + static_cast<std::ptrdiff_t>(at + 8)) == type)
      return true;
    at += 12 + be32(bytes, at);
  }
  return false;
}

void expectEncodedEqual(const Image& read, const Image& written, TransferCurve curve, bool alpha) {
  ASSERT_EQ(read.width(), written.width());
  ASSERT_EQ(read.height(), written.height());
  for (int y = 0; y < read.height(); ++y) {
    for (int x = 0; x < read.width(); ++x) {
      const Rgba& r = read.at(x, y);
      const Rgba& w = written.at(x, y);
      SCOPED_TRACE(testing::Message() << "pixel " << x << "," << y);
      EXPECT_EQ(encode8(r.r, curve), encode8(w.r, curve));
      EXPECT_EQ(encode8(r.g, curve), encode8(w.g, curve));
      EXPECT_EQ(encode8(r.b, curve), encode8(w.b, curve));
      EXPECT_EQ(encode8(r.a), alpha ? encode8(w.a) : 255);
      // What was read is exactly the decoded byte.
      EXPECT_EQ(r.r, decode8(encode8(w.r, curve), curve));
    }
  }
}

TEST(PngIo, OpaqueImageRoundTripsAsRgb) {
  ScratchFolder folder;
  const Image image = testPattern();
  writePng(folder.file("a.png"), image);
  EXPECT_EQ(pngColourType(folder.file("a.png")), 2);
  EXPECT_FALSE(hasPngChunk(folder.file("a.png"), "sRGB"));
  expectEncodedEqual(readPng(folder.file("a.png")), image, TransferCurve::Linear, false);
}

TEST(PngIo, TransparentImageRoundTripsAsRgba) {
  ScratchFolder folder;
  const Image image = testPattern(true);
  writePng(folder.file("a.png"), image);
  EXPECT_EQ(pngColourType(folder.file("a.png")), 6);
  expectEncodedEqual(readPng(folder.file("a.png")), image, TransferCurve::Linear, true);
}

TEST(PngIo, AlphaCanBeForcedOrDropped) {
  ScratchFolder folder;
  ImageWriteOptions always;
  always.alpha = AlphaChannel::Always;
  writePng(folder.file("opaque.png"), testPattern(), always);
  EXPECT_EQ(pngColourType(folder.file("opaque.png")), 6);
  ImageWriteOptions never;
  never.alpha = AlphaChannel::Never;
  writePng(folder.file("flat.png"), testPattern(true), never);
  EXPECT_EQ(pngColourType(folder.file("flat.png")), 2);
  expectEncodedEqual(readPng(folder.file("flat.png")), testPattern(true), TransferCurve::Linear, false);
}

TEST(PngIo, SrgbImageRoundTripsAndIsTagged) {
  ScratchFolder folder;
  ImageWriteOptions options;
  options.curve = TransferCurve::Srgb;
  const Image image = testPattern();
  writePng(folder.file("s.png"), image, options);
  EXPECT_TRUE(hasPngChunk(folder.file("s.png"), "sRGB"));
  expectEncodedEqual(readPng(folder.file("s.png"), TransferCurve::Srgb), image, TransferCurve::Srgb, false);
  // Read as linear, the stored bytes are the sRGB-encoded values.
  EXPECT_EQ(encode8(readPng(folder.file("s.png")).at(3, 2).g),
            encode8(image.at(3, 2).g, TransferCurve::Srgb));
}

TEST(PngIo, ReadsPalettePngFromAnotherEncoder) {
  const Image image = readPng(std::string(LANCER_TEST_DATA_DIR) + "/image/palette.png");
  ASSERT_EQ(image.width(), 4);
  ASSERT_EQ(image.height(), 2);
  const std::vector<std::array<int, 3>> expected = {{255, 0, 0},     {0, 255, 0},   {0, 0, 255},
                                                    {255, 255, 255}, {0, 0, 0},     {128, 128, 128},
                                                    {10, 20, 30},    {200, 100, 50}};
  for (int i = 0; i < 8; ++i) {
    const Rgba& p = image.pixels()[static_cast<std::size_t>(i)];
    EXPECT_EQ((std::array<int, 3>{encode8(p.r), encode8(p.g), encode8(p.b)}),
              expected[static_cast<std::size_t>(i)]);
    EXPECT_EQ(p.a, 1.0f);
  }
  EXPECT_EQ(readPng(std::string(LANCER_TEST_DATA_DIR) + "/image/interlaced.png"), image);
}

TEST(PngIo, ReadsSixteenBitGreyWithAlpha) {
  const Image image = readPng(std::string(LANCER_TEST_DATA_DIR) + "/image/grey_alpha16.png");
  ASSERT_EQ(image.width(), 3);
  ASSERT_EQ(image.height(), 1);
  const int grey[] = {0, 128, 255};
  for (int x = 0; x < 3; ++x) {
    EXPECT_EQ(encode8(image.at(x, 0).r), grey[x]);
    EXPECT_EQ(encode8(image.at(x, 0).g), grey[x]);
    EXPECT_EQ(encode8(image.at(x, 0).b), grey[x]);
    EXPECT_EQ(encode8(image.at(x, 0).a), 128);
  }
}

TEST(BmpWriter, HeaderFieldsArePerTheSpec) {
  const Image image = testPattern();  // 7 wide: 21 bytes of pixels + 3 of padding per row
  const std::vector<std::uint8_t> bmp = encodeBmp(image);
  ASSERT_EQ(bmp.size(), 54u + 24u * 5u);
  EXPECT_EQ(bmp[0], 'B');
  EXPECT_EQ(bmp[1], 'M');
  EXPECT_EQ(le32(bmp, 2), bmp.size());  // file size
  EXPECT_EQ(le32(bmp, 6), 0u);          // reserved
  EXPECT_EQ(le32(bmp, 10), 54u);        // pixel data offset
  EXPECT_EQ(le32(bmp, 14), 40u);        // BITMAPINFOHEADER
  EXPECT_EQ(le32(bmp, 18), 7u);         // width
  EXPECT_EQ(le32(bmp, 22), 5u);         // height > 0: bottom-up
  EXPECT_EQ(le16(bmp, 26), 1u);         // planes
  EXPECT_EQ(le16(bmp, 28), 24u);        // bits per pixel
  EXPECT_EQ(le32(bmp, 30), 0u);         // BI_RGB
  EXPECT_EQ(le32(bmp, 34), 24u * 5u);   // image size
  EXPECT_EQ(le32(bmp, 46), 0u);         // colours used
}

TEST(BmpWriter, RowsAreBottomUpBgrPaddedToFourBytes) {
  const Image image = testPattern();
  const std::vector<std::uint8_t> bmp = encodeBmp(image);
  for (int fileRow = 0; fileRow < 5; ++fileRow) {
    const int y = 4 - fileRow;
    const std::size_t rowStart = 54 + 24 * static_cast<std::size_t>(fileRow);
    for (int x = 0; x < 7; ++x) {
      const Rgba& p = image.at(x, y);
      const std::size_t at = rowStart + 3 * static_cast<std::size_t>(x);
      EXPECT_EQ(bmp[at], encode8(p.b));
      EXPECT_EQ(bmp[at + 1], encode8(p.g));
      EXPECT_EQ(bmp[at + 2], encode8(p.r));
    }
    for (std::size_t pad = 21; pad < 24; ++pad)
      EXPECT_EQ(bmp[rowStart + pad], 0) << "padding of row " << fileRow;
  }
}

TEST(BmpWriter, WidthsThatAreMultiplesOfFourHaveNoPadding) {
  EXPECT_EQ(encodeBmp(Image(4, 3)).size(), 54u + 12u * 3u);
  EXPECT_EQ(encodeBmp(Image(1, 1)).size(), 54u + 4u);
}

TEST(PpmWriter, IsP6WithMaxval255AndRowsFromTheTop) {
  const Image image = testPattern();
  const std::vector<std::uint8_t> ppm = encodePpm(image, TransferCurve::Srgb);
  const std::string header = "P6\n7 5\n255\n";
  ASSERT_EQ(ppm.size(), header.size() + 7 * 5 * 3);
  EXPECT_EQ(std::string(ppm.begin(), ppm.begin() + static_cast<std::ptrdiff_t>(header.size())), header);
  const std::size_t at = header.size() + (2 * 7 + 3) * 3;  // pixel (3, 2)
  EXPECT_EQ(ppm[at], encode8(image.at(3, 2).r, TransferCurve::Srgb));
  EXPECT_EQ(ppm[at + 1], encode8(image.at(3, 2).g, TransferCurve::Srgb));
  EXPECT_EQ(ppm[at + 2], encode8(image.at(3, 2).b, TransferCurve::Srgb));
}

TEST(WriteImage, ExtensionPicksTheFormatIgnoringCase) {
  EXPECT_EQ(imageFormatFromPath("a/b.PNG"), ImageFormat::Png);
  EXPECT_EQ(imageFormatFromPath("x.Bmp"), ImageFormat::Bmp);
  EXPECT_EQ(imageFormatFromPath("x.ppm"), ImageFormat::Ppm);
  EXPECT_EQ(imageFormatFromPath("dir.v2/x.gif"), ImageFormat::Gif);

  ScratchFolder folder;
  const Image image = testPattern();
  writeImage(folder.file("a.BMP"), image);
  EXPECT_EQ(readBytes(folder.file("a.BMP")), encodeBmp(image));
  writeImage(folder.file("a.ppm"), image);
  EXPECT_EQ(readBytes(folder.file("a.ppm")), encodePpm(image));
  writeImage(folder.file("a.Png"), image);
  expectEncodedEqual(readPng(folder.file("a.Png")), image, TransferCurve::Linear, false);
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"a.BMP", "a.Png", "a.ppm"}));
}

TEST(WriteImage, GifIsASingleFrameWithoutLoopBlock) {
  ScratchFolder folder;
  const Image image = testPattern();  // 35 colours: stored exactly
  writeImage(folder.file("still.gif"), image);
  const test::DecodedGif gif = test::decodeGif(folder.file("still.gif"));
  ASSERT_EQ(gif.error, "");
  EXPECT_EQ(gif.width, 7);
  EXPECT_EQ(gif.height, 5);
  ASSERT_EQ(gif.frames.size(), 1u);
  EXPECT_FALSE(gif.loopCount.has_value());
  EXPECT_EQ(gif.frames[0].canvas, encodeImage8(image, TransferCurve::Linear, 3));
}

}  // namespace
}  // namespace lancer
