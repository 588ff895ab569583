// ImageRowWriter: PNG, BMP and PPM written row by row are byte-for-byte the files writeImage writes
// for the whole image, and a write that fails or is abandoned leaves the old file and no temporary.
#include "lancer/image/image_row_writer.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "support/file_size_limit.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"
#include "support/test_images.hpp"

namespace lancer {
namespace {

using test::messageOf;
using test::readBytes;
using test::ScratchFolder;

const std::vector<std::uint8_t> kOldContent = {'o', 'l', 'd', '\n'};

// 77 x 45: neither side a multiple of 32 or of 4 (BMP pads its rows), with partial alpha.
Image picture() {
  Image image = test::shadedSphere(77, 45, 0.3f);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) image.at(x, y).a = static_cast<float>((x + 2 * y) % 11) / 10.0f;
  image.at(3, 4) = {-1, 2, 0.5f, 1};  // out-of-range values clamp
  return image;
}

// Hands the rows over in bands of `bandRows` (the last one shorter), as renderBands does.
void writeInBands(ImageRowWriter& writer, const Image& image, int bandRows) {
  for (int y0 = 0; y0 < image.height(); y0 += bandRows)
    writer.writeRows(image.crop(0, y0, image.width(), std::min(bandRows, image.height() - y0)));
}

struct Case {
  std::string extension;
  AlphaChannel alpha;
  TransferCurve curve;
};

class RowWriterMatchesWholeImage : public testing::TestWithParam<Case> {};

TEST_P(RowWriterMatchesWholeImage, ForAnyBandHeight) {
  const Case& c = GetParam();
  ScratchFolder folder;
  const Image image = picture();
  ImageWriteOptions options;
  options.alpha = c.alpha;
  options.curve = c.curve;
  writeImage(folder.file("whole" + c.extension), image, options);
  const std::vector<std::uint8_t> whole = readBytes(folder.file("whole" + c.extension));
  ASSERT_GT(whole.size(), 1000u);  // a real picture, not an empty file
  for (int bandRows : {1, 32, 45, 7}) {
    SCOPED_TRACE(bandRows);
    const std::string path = folder.file("rows" + c.extension);
    ImageRowWriter writer(path, image.width(), image.height(), options);
    writeInBands(writer, image, bandRows);
    EXPECT_EQ(writer.rowsWritten(), image.height());
    writer.commit();
    EXPECT_EQ(readBytes(path), whole);
  }
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, RowWriterMatchesWholeImage,
                         testing::Values(Case{".png", AlphaChannel::Never, TransferCurve::Linear},
                                         Case{".png", AlphaChannel::Always, TransferCurve::Linear},
                                         Case{".png", AlphaChannel::Never, TransferCurve::Srgb},
                                         Case{".png", AlphaChannel::Always, TransferCurve::Srgb},
                                         Case{".bmp", AlphaChannel::Never, TransferCurve::Linear},
                                         Case{".bmp", AlphaChannel::Always, TransferCurve::Srgb},
                                         Case{".ppm", AlphaChannel::Never, TransferCurve::Linear},
                                         Case{".ppm", AlphaChannel::Always, TransferCurve::Srgb}),
                         [](const testing::TestParamInfo<Case>& param) {
                           const Case& c = param.param;
                           return c.extension.substr(1) +
                                  (c.alpha == AlphaChannel::Always ? "Alpha" : "Opaque") +
                                  (c.curve == TransferCurve::Srgb ? "Srgb" : "Linear");
                         });

TEST(ImageRowWriter, AbandonedPartWayLeavesTheOldFileAndNoTemporary) {
  for (const std::string extension : {".png", ".bmp", ".ppm"}) {
    SCOPED_TRACE(extension);
    ScratchFolder folder;
    const std::string path = folder.file("out" + extension);
    test::writeBytes(path, kOldContent);
    {
      ImageWriteOptions options;
      options.alpha = AlphaChannel::Never;
      ImageRowWriter writer(path, 77, 45, options);
      writer.writeRows(picture().crop(0, 0, 77, 32));  // then the render stops (Ctrl-C, an error)
      EXPECT_EQ(folder.entries().size(), 2u);          // the file and the temporary beside it
    }
    test::expectOnlyFile(folder, "out" + extension, kOldContent);
  }
}

TEST(ImageRowWriter, RefusesWhatCannotBeStreamed) {
  ScratchFolder folder;
  ImageWriteOptions opaque;
  opaque.alpha = AlphaChannel::Never;
  EXPECT_EQ(
      messageOf([&] { ImageRowWriter(folder.file("a.gif"), 4, 4, opaque); }),
      folder.file("a.gif") + ": error: a GIF cannot be written row by row (its palette needs every pixel)");
  EXPECT_EQ(
      messageOf([&] { ImageRowWriter(folder.file("big.bmp"), 40000, 40000, opaque); }),
      folder.file("big.bmp") + ": error: a 40000x40000 image is too large for BMP (4 GiB at most); use .png");
  EXPECT_THROW(ImageRowWriter(folder.file("a.png"), 4, 4, ImageWriteOptions{}),
               std::invalid_argument);  // Auto
  EXPECT_TRUE(folder.entries().empty());

  ImageRowWriter writer(folder.file("a.ppm"), 4, 2, opaque);
  EXPECT_THROW(writer.writeRow(Image(5, 1).row(0)), std::invalid_argument);  // wrong width
  writer.writeRows(Image(4, 1));
  EXPECT_THROW(writer.commit(), std::logic_error);  // a row is missing
  EXPECT_TRUE(folder.entries().empty());
}

// Streams `path` under a 4 KiB file size limit. Returns the InputError's message, marked
// " (at commit)" when every row got through and only the commit failed.
std::string streamUnderFileSizeLimit(const std::string& path) {
  return test::underFileSizeLimit(4096, [&] {
    ImageWriteOptions options;
    options.alpha = AlphaChannel::Never;
    const Image image = test::noise(200, 200);  // 120 KB in every format
    int row = 0;
    std::string message = messageOf([&] {
      ImageRowWriter writer(path, image.width(), image.height(), options);
      for (; row < image.height(); ++row) writer.writeRow(image.row(row));
      writer.commit();
    });
    if (row == image.height()) message += " (at commit)";
    return message;
  });
}

TEST(ImageRowWriter, FailedWriteStopsEarlyAndKeepsTheOldFile) {
  for (const std::string extension : {".png", ".bmp", ".ppm"}) {
    SCOPED_TRACE(extension);
    ScratchFolder folder;
    const std::string path = folder.file("out" + extension);
    test::writeBytes(path, kOldContent);
    // The writes reach the file (stdio buffers 64 KiB, deflate some blocks) well before the last
    // row, so the error stops the rows there, not at commit.
    EXPECT_EQ(streamUnderFileSizeLimit(path),
              path +
                  ": error: writing failed: the file would exceed the file size limit (see 'ulimit -f'); "
                  "the existing file was left unchanged");
    test::expectOnlyFile(folder, "out" + extension, kOldContent);
  }
}

}  // namespace
}  // namespace lancer
