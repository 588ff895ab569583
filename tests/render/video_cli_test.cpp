// `lancer animate -o x.mp4|x.webm` checked with FFmpeg's own tools when they are installed (Debian's
// ffmpeg package; the test skips without them): ffprobe reads the stream, and ffmpeg's decoding of the
// first frame matches the frame lancer renders as a PNG. Stills from `lancer render` carry the DPI and
// the command line.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lancer/image/image_io.hpp"
#include "lancer/image/pixel_encoding.hpp"
#include "lancer/image/video_writer.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"
#include "support/test_images.hpp"

#if LANCER_TEST_FFMPEG
extern "C" {
#include <libavutil/version.h>
}
#endif

namespace lancer {
namespace {

using test::quoted;

bool ffmpegToolsInstalled() {
  return test::runShell("command -v ffprobe >/dev/null && command -v ffmpeg >/dev/null").exitCode == 0;
}

// 8-bit RGB of a PNG decoded with the sRGB curve: the samples as stored.
std::vector<std::uint8_t> storedRgb(const std::string& path) {
  return encodeImage8(readPng(path), TransferCurve::Linear, 3);
}

void checkVideo(const char* extension, const char* codec) {
  if (!videoSupported()) GTEST_SKIP() << "built without FFmpeg";
  if (!ffmpegToolsInstalled())
    GTEST_SKIP() << "ffprobe and ffmpeg are not installed (apt-get install ffmpeg)";
  const test::ScratchFolder folder;
  const std::string scene = quoted(test::kTurntableScene);
  const std::string video = folder.file(std::string("turn.") + extension);
  ASSERT_EQ(test::runCli("animate -q " + scene + " -o " + quoted(video)).exitCode, 0);
  ASSERT_EQ(test::runCli("animate -q " + scene + " -o " + quoted(folder.file("f_%02d.png"))).exitCode, 0);
  const test::CommandResult probe = test::runShell(
      "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
      "stream=codec_name,width,height,pix_fmt,nb_read_frames -of csv=p=0 " +
      quoted(video));
  EXPECT_EQ(probe.output, std::string(codec) + ",64,48,yuv420p,4\n");
  const test::CommandResult first = test::runShell("ffmpeg -v error -i " + quoted(video) + " -frames:v 1 " +
                                                   quoted(folder.file("first.png")) + " 2>&1");
  ASSERT_EQ(first.exitCode, 0) << first.output;
  // 4:2:0 chroma and lossy coding: close, not equal.
  const test::SampleError error =
      test::sampleError(storedRgb(folder.file("first.png")), storedRgb(folder.file("f_00.png")));
  EXPECT_LT(error.mean, 3.0);
  const test::CommandResult tags =
      test::runShell("ffprobe -v error -show_entries format_tags=comment -of csv=p=0 " + quoted(video));
  EXPECT_NE(tags.output.find("lancer animate -q"), std::string::npos) << tags.output;
}

TEST(VideoCli, Mp4MatchesTheRenderedFrames) { checkVideo("mp4", "h264"); }
TEST(VideoCli, WebmMatchesTheRenderedFrames) { checkVideo("webm", "vp9"); }

#if LANCER_TEST_FFMPEG
// FFmpeg is loaded when a video is first written: a library that cannot be loaded (here a broken
// libavutil found first on LD_LIBRARY_PATH) is a one-line error naming the video, and no file.
TEST(VideoCli, FfmpegThatCannotBeLoadedIsAClearError) {
  const test::ScratchFolder folder;
  const std::string library = "libavutil.so." AV_STRINGIFY(LIBAVUTIL_VERSION_MAJOR);
  folder.write(library, "not a library");
  const std::string video = folder.file("turn.mp4");
  const test::CommandResult result =
      test::runCli("animate -q " + quoted(test::kTurntableScene) + " -o " + quoted(video),
                   "env LD_LIBRARY_PATH=" + quoted(folder.path().string()));
  EXPECT_EQ(result.exitCode, 2) << result.output;
  test::expectContainsAll(result.output, {video, "cannot load FFmpeg", "libavcodec"});
  EXPECT_EQ(folder.entries(), std::vector<std::string>{library});  // no video, no temporary file
}
#endif

TEST(StillCli, PngAndJpegRecordTheDpiAndTheCommandLine) {
  const test::ScratchFolder folder;
  const std::string scene = quoted(test::kTurntableScene);
  ASSERT_EQ(test::runCli("render -q " + scene + " --dpi 300 -o " + quoted(folder.file("a.png"))).exitCode, 0);
  const std::vector<std::uint8_t> png = test::readBytes(folder.file("a.png"));
  const std::string text(png.begin(), png.end());
  EXPECT_NE(text.find(std::string("pHYs\0\0\x2e\x23\0\0\x2e\x23\x01", 13)), std::string::npos);
  EXPECT_NE(text.find(std::string("tEXtSoftware\0lancer ", 20)), std::string::npos);
  EXPECT_NE(text.find(std::string("tEXtComment\0lancer render -q ", 29)), std::string::npos);
  EXPECT_NE(text.find("--dpi 300 -o"), std::string::npos);

  ASSERT_EQ(test::runCli("render -q " + scene + " --dpi 150 --quality 80 -o " + quoted(folder.file("a.jpg")))
                .exitCode,
            0);
  const std::vector<std::uint8_t> jpeg = test::readBytes(folder.file("a.jpg"));
  ASSERT_GT(jpeg.size(), 20u);
  EXPECT_EQ(std::string(jpeg.begin() + 6, jpeg.begin() + 11), std::string("JFIF\0", 5));
  EXPECT_EQ(jpeg[13], 1);                    // dots per inch
  EXPECT_EQ(jpeg[14] << 8 | jpeg[15], 150);  // X density
  const std::string jpegText(jpeg.begin(), jpeg.end());
  EXPECT_NE(jpegText.find("--quality 80"), std::string::npos);  // the COM marker

  ASSERT_EQ(test::runCli("render -q " + scene + " --lossless -o " + quoted(folder.file("a.webp"))).exitCode,
            0);
  const std::vector<std::uint8_t> webp = test::readBytes(folder.file("a.webp"));
  EXPECT_EQ(std::string(webp.begin() + 8, webp.begin() + 12), "WEBP");
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"a.jpg", "a.png", "a.webp"}));
}

}  // namespace
}  // namespace lancer
