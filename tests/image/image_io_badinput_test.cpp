// Bad paths and bad files for the image readers and writers: each checks the exact message.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lancer/image/image_io.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

using test::messageOf;
using test::ScratchFolder;

TEST(ImageIoBadInput, UnknownExtensionNamesTheFileAndTheSupportedOnes) {
  ScratchFolder folder;
  const Image image(2, 2);
  const std::string path = folder.file("out.tif");
  EXPECT_EQ(
      messageOf([&] { writeImage(path, image); }),
      path +
          ": error: unknown image format: '.tif'; the supported extensions are .png, .jpg, .jpeg, .webp, "
          ".bmp, .ppm, .gif, .exr");
  EXPECT_EQ(messageOf([&] { writeImage(folder.file("out"), image); }),
            folder.file("out") +
                ": error: unknown image format: no extension; the supported extensions are "
                ".png, .jpg, .jpeg, .webp, .bmp, .ppm, .gif, .exr");
  EXPECT_EQ(messageOf([] { static_cast<void>(imageFormatFromPath("renders.png/out")); }),
            "renders.png/out: error: unknown image format: no extension; the supported extensions are .png, "
            ".jpg, .jpeg, .webp, .bmp, .ppm, .gif, .exr");
  EXPECT_TRUE(folder.entries().empty());
}

TEST(ImageIoBadInput, MissingPngFile) {
  EXPECT_EQ(messageOf([] { readPng("/nonexistent/lancer/x.png"); }),
            "/nonexistent/lancer/x.png: error: cannot open the file: No such file or directory");
}

TEST(ImageIoBadInput, FolderInsteadOfAPng) {
  ScratchFolder folder;
  EXPECT_EQ(messageOf([&] { readPng(folder.path().string()); }),
            folder.path().string() + ": error: cannot read the file: Is a directory");
}

TEST(ImageIoBadInput, FileThatIsNotAPng) {
  ScratchFolder folder;
  test::writeBytes(folder.file("x.png"), {'P', '6', '\n', '1', ' ', '1', '\n', '2', '5', '5', '\n', 0, 0, 0});
  EXPECT_EQ(messageOf([&] { readPng(folder.file("x.png")); }),
            folder.file("x.png") + ":@0: error: not a PNG file (the 8-byte PNG signature is missing)");
  test::writeBytes(folder.file("empty.png"), {});
  EXPECT_EQ(messageOf([&] { readPng(folder.file("empty.png")); }),
            folder.file("empty.png") + ":@0: error: not a PNG file (the 8-byte PNG signature is missing)");
}

TEST(ImageIoBadInput, TruncatedPng) {
  ScratchFolder folder;
  std::vector<std::uint8_t> bytes = test::readBytes(std::string(LANCER_TEST_DATA_DIR) + "/image/palette.png");
  bytes.resize(bytes.size() - 30);
  test::writeBytes(folder.file("cut.png"), bytes);
  const std::string message = messageOf([&] { readPng(folder.file("cut.png")); });
  EXPECT_EQ(message.rfind(folder.file("cut.png") + ": error: unreadable PNG: ", 0), 0u) << message;
}

void appendPngChunk(std::vector<std::uint8_t>& png, const std::vector<std::uint8_t>& typeAndData) {
  const std::size_t length = typeAndData.size() - 4;
  for (int shift = 24; shift >= 0; shift -= 8) png.push_back(static_cast<std::uint8_t>(length >> shift));
  png.insert(png.end(), typeAndData.begin(), typeAndData.end());
  std::uint32_t crc = 0xffffffffu;  // CRC-32 as in the PNG specification, annex D
  for (std::uint8_t byte : typeAndData) {
    crc ^= byte;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  crc ^= 0xffffffffu;
  for (int shift = 24; shift >= 0; shift -= 8) png.push_back(static_cast<std::uint8_t>(crc >> shift));
}

// A PNG whose header claims 60000 x 60000 pixels, followed by an empty IDAT (valid CRCs).
std::vector<std::uint8_t> hugePngHeader() {
  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  appendPngChunk(png, {'I', 'H', 'D', 'R', 0, 0, 0xea, 0x60, 0, 0, 0xea, 0x60, 8, 2, 0, 0, 0});
  appendPngChunk(png, {'I', 'D', 'A', 'T'});
  return png;
}

TEST(ImageIoBadInput, PngClaimingAHugeSizeIsRefusedBeforeAllocating) {
  ScratchFolder folder;
  test::writeBytes(folder.file("huge.png"), hugePngHeader());
  EXPECT_EQ(messageOf([&] { readPng(folder.file("huge.png")); }),
            folder.file("huge.png") +
                ": error: unreadable PNG: image too large: 60000x60000 pixels (at most 67108864)");
}

TEST(ImageIoBadInput, EmptyImageCannotBePng) {
  ScratchFolder folder;
  EXPECT_EQ(messageOf([&] { writePng(folder.file("e.png"), Image()); }),
            folder.file("e.png") + ": error: cannot write an empty (0-pixel) PNG");
}

TEST(ImageIoBadInput, GifOptionsOutOfRange) {
  ScratchFolder folder;
  const std::string path = folder.file("a.gif");
  GifOptions options;
  options.fps = 0;
  EXPECT_EQ(messageOf([&] { GifWriter(path, 4, 4, options); }),
            path + ": error: the frame rate must be positive, not 0");
  options.fps = 10;
  options.loopCount = 70000;
  EXPECT_EQ(messageOf([&] { GifWriter(path, 4, 4, options); }),
            path + ": error: the loop count must be 0 (forever) to 65535, not 70000");
  EXPECT_EQ(messageOf([&] { GifWriter(path, 0, 4); }),
            path + ": error: a GIF must be 1..65535 pixels on each side, not 0x4");
  EXPECT_TRUE(folder.entries().empty());
}

}  // namespace
}  // namespace lancer
