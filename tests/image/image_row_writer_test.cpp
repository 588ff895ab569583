// ImageRowWriter: PNG, BMP and PPM written row by row are byte-for-byte the files writeImage writes
// for the whole image, and a write that fails or is abandoned leaves the old file and no temporary.
#include "lancer/image/image_row_writer.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/image_test_util.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

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

std::string messageOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
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
    EXPECT_EQ(readBytes(path), kOldContent);
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"out" + extension});
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

// Noise does not compress: every format's file is about 3 bytes per pixel.
Image noise(int width, int height) {
  Image image(width, height);
  std::uint32_t state = 12345;
  for (Rgba& p : image.pixels()) {
    auto next = [&] {
      state = state * 1664525u + 1013904223u;
      return static_cast<float>(state >> 24) / 255.0f;
    };
    p = {next(), next(), next(), 1};
  }
  return image;
}

// Streams `extension` in a forked child limited to 4 KiB per file (RLIMIT_FSIZE, as `ulimit -f`),
// with SIGXFSZ ignored so the write fails with EFBIG. Returns the InputError's message and the row
// it was thrown at, sent back through a pipe.
std::string streamUnderFileSizeLimit(const std::string& path) {
  int pipeEnds[2];
  if (::pipe(pipeEnds) != 0) return "(pipe failed)";
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(pipeEnds[0]);
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    std::string message = "(no InputError)";
    ImageWriteOptions options;
    options.alpha = AlphaChannel::Never;
    const Image image = noise(200, 200);  // 120 KB in every format
    int row = 0;
    try {
      ImageRowWriter writer(path, image.width(), image.height(), options);
      for (; row < image.height(); ++row) writer.writeRow(image.row(row));
      writer.commit();
    } catch (const InputError& e) {
      message = e.what();
    }
    if (row == image.height()) message += " (at commit)";
    const ssize_t written = ::write(pipeEnds[1], message.data(), message.size());
    ::_exit(written == static_cast<ssize_t>(message.size()) ? 0 : 1);
  }
  ::close(pipeEnds[1]);
  std::string message;
  char buffer[512];
  ssize_t n;
  while ((n = ::read(pipeEnds[0], buffer, sizeof buffer)) > 0)
    message.append(buffer, static_cast<std::size_t>(n));
  ::close(pipeEnds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return "(child failed: status " + std::to_string(status) + ")";
  return message;
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
    EXPECT_EQ(readBytes(path), kOldContent);
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"out" + extension});
  }
}

}  // namespace
}  // namespace lancer
