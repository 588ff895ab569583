// MP4 and WebM written by VideoWriter and decoded again by FFmpeg's own demuxers and decoders: the
// codec, the size (odd sides padded for H.264), the frame count and rate, and each frame's pixels
// within 4:2:0 and lossy coding's tolerance. A failed or unfinished video leaves nothing behind.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lancer/image/animation_writer.hpp"
#include "lancer/image/pixel_encoding.hpp"
#include "lancer/image/video_writer.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"
#include "support/test_images.hpp"

#if LANCER_TEST_FFMPEG
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}
#endif

namespace lancer {
namespace {

#if LANCER_TEST_FFMPEG
struct DecodedVideo {
  std::string codec;
  int width = 0, height = 0;
  double fps = 0;
  std::string comment;
  std::vector<std::vector<std::uint8_t>> frames;  // RGB24 at the coded size
};

DecodedVideo decode(const std::string& path) {
  DecodedVideo video;
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) return video;
  avformat_find_stream_info(format, nullptr);
  const AVStream* stream = format->streams[0];
  const AVCodec* decoder = avcodec_find_decoder(stream->codecpar->codec_id);
  AVCodecContext* codec = avcodec_alloc_context3(decoder);
  avcodec_parameters_to_context(codec, stream->codecpar);
  avcodec_open2(codec, decoder, nullptr);
  video.codec = decoder->name;
  video.width = codec->width;
  video.height = codec->height;
  video.fps = av_q2d(stream->avg_frame_rate);
  if (const AVDictionaryEntry* entry = av_dict_get(format->metadata, "comment", nullptr, 0))
    video.comment = entry->value;
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  SwsContext* sws = nullptr;
  const auto receive = [&] {
    while (avcodec_receive_frame(codec, frame) == 0) {
      // Back to RGB with the matrix the stream is tagged with (BT.709, limited range).
      sws = sws_getCachedContext(sws, frame->width, frame->height, static_cast<AVPixelFormat>(frame->format),
                                 frame->width, frame->height, AV_PIX_FMT_RGB24,
                                 SWS_BICUBIC | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
      sws_setColorspaceDetails(sws, sws_getCoefficients(SWS_CS_ITU709), 0,
                               sws_getCoefficients(SWS_CS_DEFAULT), 1, 0, 1 << 16, 1 << 16);
      std::vector<std::uint8_t> rgb(static_cast<std::size_t>(frame->width) * frame->height * 3);
      std::uint8_t* out[1] = {rgb.data()};
      const int stride[1] = {frame->width * 3};
      sws_scale(sws, frame->data, frame->linesize, 0, frame->height, out, stride);
      video.frames.push_back(rgb);
    }
  };
  while (av_read_frame(format, packet) >= 0) {
    avcodec_send_packet(codec, packet);
    av_packet_unref(packet);
    receive();
  }
  avcodec_send_packet(codec, nullptr);
  receive();
  sws_freeContext(sws);
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&codec);
  avformat_close_input(&format);
  return video;
}

// The top-left width x height of a decoded frame, and the column past it (the padding) if any.
std::vector<std::uint8_t> crop(const std::vector<std::uint8_t>& rgb, int codedWidth, int width, int height) {
  std::vector<std::uint8_t> out;
  for (int y = 0; y < height; ++y)
    out.insert(out.end(), rgb.begin() + static_cast<std::ptrdiff_t>(3 * y * codedWidth),
               rgb.begin() + static_cast<std::ptrdiff_t>(3 * (y * codedWidth + width)));
  return out;
}

void writeVideo(const std::string& path, VideoContainer container, int width, int height, int frames,
                std::string* note = nullptr) {
  VideoOptions options;
  options.fps = 8;
  options.metadata.software = "lancer 9.9.9";
  options.metadata.command = "lancer animate x.msh";
  VideoWriter writer(path, container, width, height, options);
  for (int k = 0; k < frames; ++k) writer.addFrame(test::shadedSphere(width, height, 0.1f * k));
  writer.finish();
  if (note != nullptr) *note = writer.note();
}

void expectFramesMatch(const DecodedVideo& video, int width, int height, int frames) {
  ASSERT_EQ(static_cast<int>(video.frames.size()), frames);
  for (int k = 0; k < frames; ++k) {
    const std::vector<std::uint8_t> truth =
        encodeImage8(test::shadedSphere(width, height, 0.1f * k), TransferCurve::Srgb, 3);
    const test::SampleError error =
        test::sampleError(crop(video.frames[k], video.width, width, height), truth);
    EXPECT_LT(error.mean, 5.0) << "frame " << k;  // a small picture: chroma at half resolution shows
  }
}

TEST(VideoWriter, Mp4IsH264WithEveryFrame) {
  const test::ScratchFolder folder;
  std::string note;
  writeVideo(folder.file("a.mp4"), VideoContainer::Mp4, 64, 48, 6, &note);
  const DecodedVideo video = decode(folder.file("a.mp4"));
  EXPECT_EQ(video.codec, "h264");
  EXPECT_EQ(video.width, 64);
  EXPECT_EQ(video.height, 48);
  EXPECT_DOUBLE_EQ(video.fps, 8);
  EXPECT_EQ(video.comment, "lancer 9.9.9: lancer animate x.msh");
  expectFramesMatch(video, 64, 48, 6);
  EXPECT_EQ(note, "");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"a.mp4"});
}

TEST(VideoWriter, Mp4OfOddSizeIsPaddedWithTheEdge) {
  const test::ScratchFolder folder;
  std::string note;
  writeVideo(folder.file("odd.mp4"), VideoContainer::Mp4, 33, 25, 2, &note);
  EXPECT_NE(
      note.find("H.264's 4:2:0 samples need even sides: the 33x25 frames are encoded as 34x26, the last "
                "column and row repeated"),
      std::string::npos)
      << note;
  const DecodedVideo video = decode(folder.file("odd.mp4"));
  EXPECT_EQ(video.width, 34);
  EXPECT_EQ(video.height, 26);
  expectFramesMatch(video, 33, 25, 2);
}

// A flat colour comes back as itself: the RGB -> YUV matrix and range the file is tagged with (BT.709,
// limited) are the ones used; a BT.601 matrix would shift this orange by more than 10 levels.
TEST(VideoWriter, FlatColourKeepsItsSamples) {
  const test::ScratchFolder folder;
  Image orange(32, 32);
  for (Rgba& pixel : orange.pixels()) pixel = Rgba{0.9f, 0.45f, 0.1f, 1.0f};
  for (const VideoContainer container : {VideoContainer::Mp4, VideoContainer::Webm}) {
    const std::string path = folder.file(container == VideoContainer::Mp4 ? "o.mp4" : "o.webm");
    VideoWriter writer(path, container, 32, 32, VideoOptions{12, TransferCurve::Linear, {}});
    writer.addFrame(orange);
    writer.finish();
    const DecodedVideo video = decode(path);
    ASSERT_EQ(video.frames.size(), 1u);
    const std::uint8_t* centre = video.frames[0].data() + 3 * (16 * 32 + 16);
    EXPECT_NEAR(centre[0], 230, 3) << path;  // round(255 * 0.9)
    EXPECT_NEAR(centre[1], 115, 3) << path;
    EXPECT_NEAR(centre[2], 26, 3) << path;
  }
}

TEST(VideoWriter, WebmIsVp9AndKeepsOddSizes) {
  const test::ScratchFolder folder;
  std::string note;
  writeVideo(folder.file("a.webm"), VideoContainer::Webm, 33, 25, 3, &note);
  const DecodedVideo video = decode(folder.file("a.webm"));
  EXPECT_EQ(video.codec, "vp9");
  EXPECT_EQ(video.width, 33);
  EXPECT_EQ(video.height, 25);
  EXPECT_EQ(video.comment, "lancer 9.9.9: lancer animate x.msh");
  expectFramesMatch(video, 33, 25, 3);
  EXPECT_EQ(note, "");
}
#endif

TEST(VideoWriterBadInput, UnfinishedOrUnwritableLeavesNothing) {
  if (!videoSupported()) {
    const test::ScratchFolder folder;
    EXPECT_NE(test::messageOf([&] {
                VideoWriter(folder.file("a.mp4"), VideoContainer::Mp4, 8, 8, {});
              }).find("built without FFmpeg (-DLANCER_FFMPEG=OFF)"),
              std::string::npos);
    EXPECT_TRUE(folder.entries().empty());
    return;
  }
  const test::ScratchFolder folder;
  {
    VideoWriter writer(folder.file("a.mp4"), VideoContainer::Mp4, 16, 16, {});
    writer.addFrame(test::shadedSphere(16, 16, 0));
  }  // never finished: an interrupted animation
  EXPECT_TRUE(folder.entries().empty());
  const std::string path = folder.file("missing/a.webm");
  EXPECT_EQ(test::messageOf([&] { VideoWriter(path, VideoContainer::Webm, 8, 8, {}); }),
            path + ": error: cannot write here: the folder '" + folder.file("missing") + "' does not exist");
  EXPECT_TRUE(folder.entries().empty());
}

TEST(VideoWriterBadInput, AnimationOptionsThatDoNotApply) {
  const test::ScratchFolder folder;
  AnimationOutputOptions options;
  options.loop = 2;
  EXPECT_EQ(
      test::messageOf([&] { AnimationWriter(folder.file("a.mp4"), 8, 8, options); }),
      "--loop: error: --loop applies to an animated .gif or .png; whether a video repeats is its player's "
      "choice");
  options = {};
  options.dither = "none";
  EXPECT_EQ(test::messageOf([&] { AnimationWriter(folder.file("a.webm"), 8, 8, options); }),
            "--dither: error: --dither applies to an animated .gif only");
  EXPECT_EQ(
      test::messageOf([&] { AnimationWriter(folder.file("a.avi"), 8, 8, {}); }),
      folder.file("a.avi") +
          ": error: an animation is written as .gif, as an animated .png, as an .mp4 (H.264) or .webm (VP9) "
          "video, or as numbered frames with %04d in the name (frame_%04d.png, .jpg, .webp, .bmp, .ppm or "
          ".exr)");
  EXPECT_TRUE(folder.entries().empty());
}

}  // namespace
}  // namespace lancer
