// Environment maps whose header claims more pixels than the file holds or the memory budget allows:
// refused before the pixels are allocated, with the size and the bytes found. A grey (Y) EXR is read
// as grey; other images and folders are named as what they are, their bytes never echoed raw. The lying EXR
// files are made byte by byte (test::exrFile): a header, then a chunk table.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "lancer/image/environment_map.hpp"
#include "lancer/image/exr_io.hpp"
#include "lancer/image/hdr_reader.hpp"
#include "lancer/util/memory_budget.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"
#include "support/test_images.hpp"

namespace lancer {
namespace {

std::string exrErrorOf(const std::string& bytes) {
  test::ScratchFolder folder;
  folder.write("map.exr", bytes);
  const std::string path = folder.file("map.exr");
  return test::messageOf([&] { readEnvironmentMap(path); });
}

TEST(EnvironmentMapSize, HdrWhoseSizeTheFileCannotHoldIsRefusedBeforeAllocating) {
  // 57 bytes claiming 23170 x 11585 pixels: 3.1 GB of pixels were taken before "the data ends".
  const std::string bytes =
      "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 11585 +X 23170\n\x02\x02"
      "\x5a"
      "\x82";
  ASSERT_EQ(bytes.size(), 57u);
  const std::string message = test::messageOf([&] { decodeRadianceHdr(bytes, "sky.hdr"); });
  EXPECT_EQ(message,
            "sky.hdr:@53: error: 'sky.hdr' is truncated or its size is corrupt: 23170 x 11585 pixels take at "
            "least 17006780 bytes of scanlines, but only 4 bytes follow the size line");
}

TEST(EnvironmentMapSize, HdrOverTheMemoryBudgetIsRefused) {
  std::string bytes = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 128 +X 256\n";
  bytes += std::string(256 * 128 * 4, '\x80');
  const std::uint64_t saved = memoryBudget();
  setMemoryBudget(100'000);
  const std::string message = test::messageOf([&] { decodeRadianceHdr(bytes, "sky.hdr"); });
  setMemoryBudget(saved);
  EXPECT_EQ(message,
            "sky.hdr: error: the 256 x 128 map in 'sky.hdr' needs 384.0 KiB, more than the memory budget of "
            "97.7 KiB; use a smaller input or raise --max-memory");
  EXPECT_EQ(decodeRadianceHdr(bytes, "sky.hdr").pixels.size(), 256u * 128u);
}

class EnvironmentMapExr : public testing::Test {
 protected:
  void SetUp() override {
    if (!exrSupported()) GTEST_SKIP() << "built without OpenEXR";
  }
};

TEST_F(EnvironmentMapExr, HeaderAttributeLongerThanTheFileIsRefusedBeforeOpenExrAllocatesIt) {
  // Found by fuzz_exr_map: 30 bytes whose attribute of an unknown type says 2 GiB; OpenEXR allocated
  // its value at that size before reading it (fuzz/regressions/exr_map/attribute_of_2gib.exr).
  std::string bytes("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
  bytes += std::string("comments\0weird\0", 15) + std::string("\xff\xff\xff\x7f", 4) + "abc";
  ASSERT_EQ(bytes.size(), 30u);
  test::ScratchFolder folder;
  folder.write("map.exr", bytes);
  const std::string path = folder.file("map.exr");
  EXPECT_EQ(test::messageOf([&] { readEnvironmentMap(path); }),
            path + ": error: '" + path +
                "' is truncated or corrupt: its header's attribute 'comments' (weird) says its value is "
                "2147483647 bytes, but the file has 3 bytes after byte 27");
}

TEST_F(EnvironmentMapExr, FileThatEndsAfterItsChunkTableIsRefused) {
  // 32768 x 16384 with ZIP: a whole table of 1024 chunks (8 KiB), and no chunk after it.
  const std::string bytes = test::exrFile(
      32768, 16384, 3, 1024, [](int, std::uint64_t start) { return start; }, "");
  const std::string message = exrErrorOf(bytes);
  EXPECT_NE(message.find("is truncated or corrupt: the chunk of row 0 is at byte 8505, but the file has 8505 "
                         "bytes"),
            std::string::npos)
      << message;
}

TEST_F(EnvironmentMapExr, EveryChunkAtOneOffsetIsRefused) {
  // A whole table whose offsets all point at one chunk (of rows 0 to 31): 11.6 KB asked for 8.6 GB.
  std::string chunk;
  test::appendLittleEndian(chunk, 0, 4);
  test::appendLittleEndian(chunk, 3000, 4);
  chunk += std::string(3000, '\0');
  const std::string bytes = test::exrFile(
      32768, 16384, 4, 512, [](int, std::uint64_t start) { return start; }, chunk);
  const std::string message = exrErrorOf(bytes);
  EXPECT_NE(message.find("the chunk of row 32 at byte"), std::string::npos) << message;
  EXPECT_NE(message.find("says it holds row 0"), std::string::npos) << message;
}

TEST_F(EnvironmentMapExr, ChunksTooSmallForTheirRowsAreRefused) {
  // ZIP chunks of 1 byte each cannot inflate to 16 rows of 32768 pixels (deflate's ratio is 1032:1).
  std::string chunks;
  for (int i = 0; i < 1024; ++i) {
    test::appendLittleEndian(chunks, static_cast<std::uint64_t>(i * 16), 4);
    test::appendLittleEndian(chunks, 1, 4);
    chunks += '\0';
  }
  const std::string bytes = test::exrFile(
      32768, 16384, 3, 1024, [](int i, std::uint64_t start) { return start + 9 * i; }, chunks);
  const std::string message = exrErrorOf(bytes);
  EXPECT_NE(message.find("the chunk of row 0 holds 1 bytes, too few for the 3145728 bytes of its 16 rows"),
            std::string::npos)
      << message;
}

TEST_F(EnvironmentMapExr, OverTheMemoryBudgetIsRefusedAndAWholeMapIsRead) {
  test::ScratchFolder folder;
  const std::string path = folder.file("map.exr");
  writeExr(path, Image(64, 32, Rgba{0.5f, 0.25f, 1, 1}));
  const std::uint64_t saved = memoryBudget();
  setMemoryBudget(10'000);
  const std::string message = test::messageOf([&] { readEnvironmentMap(path); });
  setMemoryBudget(saved);
  EXPECT_NE(message.find("the 64x32 EXR image '" + path + "' needs 32.0 KiB, more than the memory budget"),
            std::string::npos)
      << message;
  const HdrImage map = readEnvironmentMap(path);
  ASSERT_EQ(map.pixels.size(), 64u * 32u);
  EXPECT_EQ(map.pixels[100], (Vec3{0.5f, 0.25f, 1}));
}

// An uncompressed single-channel EXR of 8 x 4 half-float `value`s in the channel `channel`.
std::string singleChannelExr(const std::string& channel, std::uint16_t value) {
  std::string rows;
  for (int y = 0; y < 4; ++y) {
    test::appendLittleEndian(rows, static_cast<std::uint64_t>(y), 4);
    test::appendLittleEndian(rows, 16, 4);
    for (int x = 0; x < 8; ++x) test::appendLittleEndian(rows, value, 2);
  }
  return test::exrFile(8, 4, 0, 4,
                       [](int i, std::uint64_t start) { return start + 24 * static_cast<std::uint64_t>(i); },
                       rows, {channel});
}

TEST_F(EnvironmentMapExr, LuminanceAloneIsReadAsGrey) {
  test::ScratchFolder folder;
  folder.write("grey.exr", singleChannelExr("Y", 0x3800));  // 0.5: a grey sky, not a black one
  const HdrImage map = readEnvironmentMap(folder.file("grey.exr"));
  ASSERT_EQ(map.pixels.size(), 32u);
  for (const Vec3& pixel : map.pixels) EXPECT_EQ(pixel, (Vec3{0.5f, 0.5f, 0.5f}));
}

TEST_F(EnvironmentMapExr, NoColourChannelIsRefused) {
  const std::string message = exrErrorOf(singleChannelExr("Z", 0x3800));
  EXPECT_NE(message.find("has no R, G, B or Y channel (its channels: Z)"), std::string::npos) << message;
}

TEST(EnvironmentMapKind, OtherImagesAreNamedAndTheirBytesNotEchoed) {
  test::ScratchFolder folder;
  folder.write("sky.hdr", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
  EXPECT_EQ(test::messageOf([&] { readEnvironmentMap(folder.file("sky.hdr")); }),
            folder.file("sky.hdr") + ": error: '" + folder.file("sky.hdr") +
                "' is a PNG image, not a Radiance .hdr or OpenEXR map (an environment map is an "
                "equirectangular image of radiance, e.g. 2048 x 1024)");
  folder.write("sky.jpg", "\xff\xd8\xff\xe0 JFIF");
  EXPECT_NE(test::messageOf([&] { readEnvironmentMap(folder.file("sky.jpg")); }).find("is a JPEG image"),
            std::string::npos);
  folder.write("odd.hdr", "\x01\x02\xfe\\sky\n");
  EXPECT_EQ(test::messageOf([&] { readEnvironmentMap(folder.file("odd.hdr")); }),
            folder.file("odd.hdr") + ": error: '" + folder.file("odd.hdr") +
                "' is not a Radiance .hdr image: the first line is \"\\x01\\x02\\xfe\\x5csky\", expected "
                "#?RADIANCE");
}

TEST(EnvironmentMapKind, AFolderIsSaidToBeAFolder) {
  test::ScratchFolder folder;
  folder.write("maps.hdr/readme.txt", "");
  EXPECT_EQ(
      test::messageOf([&] { readEnvironmentMap(folder.file("maps.hdr")); }),
      folder.file("maps.hdr") + ": error: '" + folder.file("maps.hdr") + "' is a folder, not a map file");
}

}  // namespace
}  // namespace lancer
