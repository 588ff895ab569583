#include "lancer/image/video_writer.hpp"

#include <fmt/format.h>

#include "lancer/util/input_error.hpp"

#if LANCER_HAVE_FFMPEG
#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "lancer/image/atomic_file.hpp"
#include "lancer/image/ffmpeg_api.hpp"
#endif

namespace lancer {

#if LANCER_HAVE_FFMPEG
namespace {

std::string avError(const FfmpegApi& av, int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av.av_strerror(code, text, sizeof text);
  return text;
}

constexpr int kIoBufferSize = 1 << 16;

// FFmpeg prints to stderr by default; the library never prints. Its last error line is kept instead,
// for the message of a failure.
std::mutex gLogMutex;
char gLastLogError[512] = {};
const FfmpegApi* gLogApi = nullptr;  // set before the callback is

void onAvLog(void* context, int level, const char* format, va_list arguments) {
  if (level > AV_LOG_ERROR) return;
  const FfmpegApi& av = *gLogApi;
  char line[512];
  int prefix = 1;
  av.av_log_format_line2(context, level, format, arguments, line, sizeof line, &prefix);
  const std::lock_guard lock(gLogMutex);
  std::snprintf(gLastLogError, sizeof gLastLogError, "%s", line);
  const std::size_t length = std::strlen(gLastLogError);
  if (length > 0 && gLastLogError[length - 1] == '\n') gLastLogError[length - 1] = 0;
}

void silenceFfmpeg(const FfmpegApi& av) {
  static std::once_flag once;
  std::call_once(once, [&av] {
    gLogApi = &av;
    av.av_log_set_callback(onAvLog);
  });
}

std::string lastLogError() {
  const std::lock_guard lock(gLogMutex);
  return gLastLogError;
}

}  // namespace

// Everything FFmpeg allocates, freed in the destructor whatever step failed.
struct VideoWriter::State {
  State(const std::string& path, const FfmpegApi& api) : av(api), file(path) {}
  ~State() {
    av.sws_freeContext(sws);
    av.av_frame_free(&frame);
    av.av_packet_free(&packet);
    av.avcodec_free_context(&codec);
    if (format != nullptr) av.avformat_free_context(format);
    if (io != nullptr) av.av_freep(&io->buffer);
    av.avio_context_free(&io);
  }

  [[noreturn]] void fail(const std::string& what, int code) {
    file.throwIfFailed();  // a failed write, with its reason
    file.discard();
    const std::string detail = lastLogError();
    throw InputError(
        SourceLocation{file.targetPath()},
        fmt::format("{}: {}{}", what, avError(av, code), detail.empty() ? "" : " (" + detail + ")"));
  }

  // libavformat's output: every write goes where the muxer's position is (the MP4 muxer seeks back
  // to fill in sizes).
  static int write(void* opaque, std::uint8_t* data, int size) {
    auto* self = static_cast<State*>(opaque);
    if (!self->file.writeAt(self->position, data, static_cast<std::size_t>(size))) return AVERROR(EIO);
    self->position += static_cast<std::uint64_t>(size);
    self->size = std::max(self->size, self->position);
    return size;
  }
  static std::int64_t seek(void* opaque, std::int64_t offset, int whence) {
    auto* self = static_cast<State*>(opaque);
    const auto size = static_cast<std::int64_t>(self->size);
    switch (whence & ~AVSEEK_FORCE) {
      case AVSEEK_SIZE:
        return size;
      case SEEK_SET:
        break;
      case SEEK_CUR:
        offset += static_cast<std::int64_t>(self->position);
        break;
      case SEEK_END:
        offset += size;
        break;
      default:
        return AVERROR(EINVAL);
    }
    if (offset < 0) return AVERROR(EINVAL);
    self->position = static_cast<std::uint64_t>(offset);
    return offset;
  }

  // Sends `input` (nullptr: the end) and writes every packet the encoder has ready.
  void encode(const AVFrame* input) {
    int code = av.avcodec_send_frame(codec, input);
    if (code < 0) fail("video encoding failed", code);
    for (;;) {
      code = av.avcodec_receive_packet(codec, packet);
      if (code == AVERROR(EAGAIN) || code == AVERROR_EOF) return;
      if (code < 0) fail("video encoding failed", code);
      av.av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      code = av.av_interleaved_write_frame(format, packet);  // takes the packet's data
      if (code < 0) fail("writing the video failed", code);
    }
  }

  const FfmpegApi& av;
  AtomicFileWriter file;
  std::uint64_t position = 0, size = 0;
  AVFormatContext* format = nullptr;
  AVIOContext* io = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* sws = nullptr;
  std::vector<std::uint8_t> rgb;  // one frame, padded to the encoded size
  std::vector<std::uint8_t> row;
  int width = 0, height = 0;  // the picture's; the codec's may be one more
  TransferCurve curve = TransferCurve::Srgb;
  std::int64_t nextPts = 0;
};

bool videoSupported() { return true; }

namespace {

// The encoder for the container, and a note when it is not the one users expect.
const AVCodec* chooseEncoder(const FfmpegApi& av, VideoContainer container, const std::string& path,
                             std::string& note) {
  if (container == VideoContainer::Webm) {
    if (const AVCodec* vp9 = av.avcodec_find_encoder_by_name("libvpx-vp9")) return vp9;
    throw InputError(SourceLocation{path},
                     "this FFmpeg has no VP9 encoder (libvpx-vp9) for WebM: write .mp4 or .gif instead");
  }
  if (const AVCodec* x264 = av.avcodec_find_encoder_by_name("libx264")) return x264;
  if (const AVCodec* h264 = av.avcodec_find_encoder(AV_CODEC_ID_H264)) {
    note = fmt::format("lancer: {}: libx264 is missing from this FFmpeg; H.264 comes from its '{}' encoder",
                       path, h264->name);
    return h264;
  }
  if (const AVCodec* mpeg4 = av.avcodec_find_encoder(AV_CODEC_ID_MPEG4)) {
    note = fmt::format(
        "lancer: {}: this FFmpeg has no H.264 encoder (libx264); the MP4 holds MPEG-4 part 2 "
        "video, which fewer slide programs play: write .webm, or install an FFmpeg with libx264",
        path);
    return mpeg4;
  }
  throw InputError(SourceLocation{path}, "this FFmpeg has no H.264 or MPEG-4 encoder: write .webm or .gif");
}

// Quality settings: visually lossless for figures (x264's CRF 18; VP9's constant quality 31, the level
// its documentation suggests for 480p-720p) at a moderate speed.
void setEncoderOptions(const FfmpegApi& av, const AVCodec* encoder, AVDictionary** options) {
  const std::string name = encoder->name;
  if (name == "libx264") {
    av.av_dict_set(options, "preset", "medium", 0);
    av.av_dict_set(options, "crf", "18", 0);
  } else if (name == "libvpx-vp9") {
    av.av_dict_set(options, "crf", "31", 0);
    av.av_dict_set(options, "b", "0", 0);  // constant quality, no bitrate target
    av.av_dict_set(options, "deadline", "good", 0);
    av.av_dict_set(options, "cpu-used", "4", 0);
    av.av_dict_set(options, "row-mt", "1", 0);
  } else {
    av.av_dict_set(options, "q", "3", 0);  // MPEG-4 part 2 and other encoders: a fixed, high quality
  }
}

}  // namespace

VideoWriter::VideoWriter(const std::string& path, VideoContainer container, int width, int height,
                         const VideoOptions& options) {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    throw InputError(SourceLocation{path},
                     fmt::format("a video of {}x{} pixels cannot be written", width, height));
  if (!(options.fps > 0)) throw InputError(SourceLocation{path}, "a video needs a frame rate above 0");
  const FfmpegApi& av = ffmpegApi(path);
  silenceFfmpeg(av);
  const AVCodec* encoder = chooseEncoder(av, container, path, note_);
  state_ = std::make_unique<State>(path, av);  // the temporary file: a bad folder fails here
  State& s = *state_;
  s.width = width;
  s.height = height;
  s.curve = options.curve;
  // 4:2:0 halves the chroma both ways; H.264 in MP4 wants even sides (VP9 takes odd ones).
  const bool even = container == VideoContainer::Mp4;
  const int codedWidth = even ? (width + 1) / 2 * 2 : width;
  const int codedHeight = even ? (height + 1) / 2 * 2 : height;
  if (codedWidth != width || codedHeight != height) {
    const std::string padding = fmt::format(
        "lancer: {}: H.264's 4:2:0 samples need even sides: the {}x{} frames are encoded as {}x{}, "
        "the last {} repeated",
        path, width, height, codedWidth, codedHeight,
        codedWidth != width && codedHeight != height ? "column and row"
                                                     : (codedWidth != width ? "column" : "row"));
    note_ = note_.empty() ? padding : note_ + "\n" + padding;
  }

  int code = av.avformat_alloc_output_context2(&s.format, nullptr,
                                               container == VideoContainer::Mp4 ? "mp4" : "webm", nullptr);
  if (code < 0 || s.format == nullptr) s.fail("cannot set up the video container", code);
  s.codec = av.avcodec_alloc_context3(encoder);
  if (s.codec == nullptr) s.fail("cannot set up the video encoder", AVERROR(ENOMEM));
  const AVRational frameRate = av.av_d2q(options.fps, 1'000'000);
  s.codec->width = codedWidth;
  s.codec->height = codedHeight;
  s.codec->pix_fmt = AV_PIX_FMT_YUV420P;
  s.codec->framerate = frameRate;
  s.codec->time_base = av_inv_q(frameRate);
  s.codec->sample_aspect_ratio = AVRational{1, 1};
  // The samples are sRGB-encoded values converted with the BT.709 matrix to limited range, tagged so.
  s.codec->colorspace = AVCOL_SPC_BT709;
  s.codec->color_primaries = AVCOL_PRI_BT709;
  s.codec->color_trc = AVCOL_TRC_IEC61966_2_1;
  s.codec->color_range = AVCOL_RANGE_MPEG;
  if ((s.format->oformat->flags & AVFMT_GLOBALHEADER) != 0) s.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  AVDictionary* encoderOptions = nullptr;
  setEncoderOptions(av, encoder, &encoderOptions);
  code = av.avcodec_open2(s.codec, encoder, &encoderOptions);
  av.av_dict_free(&encoderOptions);
  if (code < 0) s.fail(fmt::format("cannot open the {} encoder", encoder->name), code);

  s.stream = av.avformat_new_stream(s.format, nullptr);
  if (s.stream == nullptr) s.fail("cannot set up the video stream", AVERROR(ENOMEM));
  s.stream->time_base = s.codec->time_base;
  s.stream->avg_frame_rate = frameRate;
  code = av.avcodec_parameters_from_context(s.stream->codecpar, s.codec);
  if (code < 0) s.fail("cannot set up the video stream", code);
  std::string comment = options.metadata.software;
  if (!options.metadata.command.empty()) comment += (comment.empty() ? "" : ": ") + options.metadata.command;
  if (!comment.empty()) av.av_dict_set(&s.format->metadata, "comment", comment.c_str(), 0);

  auto* buffer = static_cast<unsigned char*>(av.av_malloc(kIoBufferSize));
  if (buffer == nullptr) s.fail("cannot set up the video output", AVERROR(ENOMEM));
  s.io = av.avio_alloc_context(buffer, kIoBufferSize, 1, &s, nullptr, &State::write, &State::seek);
  if (s.io == nullptr) {
    av.av_free(buffer);
    s.fail("cannot set up the video output", AVERROR(ENOMEM));
  }
  s.format->pb = s.io;
  s.format->flags |= AVFMT_FLAG_CUSTOM_IO;
  code = av.avformat_write_header(s.format, nullptr);
  if (code < 0) s.fail("cannot write the video header", code);

  s.frame = av.av_frame_alloc();
  s.packet = av.av_packet_alloc();
  if (s.frame == nullptr || s.packet == nullptr) s.fail("cannot set up the video frames", AVERROR(ENOMEM));
  s.frame->format = AV_PIX_FMT_YUV420P;
  s.frame->width = codedWidth;
  s.frame->height = codedHeight;
  s.frame->colorspace = AVCOL_SPC_BT709;
  s.frame->color_range = AVCOL_RANGE_MPEG;
  code = av.av_frame_get_buffer(s.frame, 0);
  if (code < 0) s.fail("cannot set up the video frames", code);
  s.sws = av.sws_getContext(codedWidth, codedHeight, AV_PIX_FMT_RGB24, codedWidth, codedHeight,
                            AV_PIX_FMT_YUV420P, SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr,
                            nullptr, nullptr);
  if (s.sws == nullptr) s.fail("cannot set up the colour conversion", AVERROR(EINVAL));
  // Full-range RGB in, BT.709 limited-range YUV out, as tagged above.
  av.sws_setColorspaceDetails(s.sws, av.sws_getCoefficients(SWS_CS_DEFAULT), 1,
                              av.sws_getCoefficients(SWS_CS_ITU709), 0, 0, 1 << 16, 1 << 16);
  s.rgb.resize(static_cast<std::size_t>(codedWidth) * static_cast<std::size_t>(codedHeight) * 3);
  s.file.throwIfFailed();
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::addFrame(const Image& image) {
  State& s = *state_;
  const FfmpegApi& av = s.av;
  if (image.width() != s.width || image.height() != s.height)
    throw std::invalid_argument(fmt::format("VideoWriter: a {}x{} frame for a {}x{} video", image.width(),
                                            image.height(), s.width, s.height));
  const int codedWidth = s.codec->width, codedHeight = s.codec->height;
  const std::size_t stride = static_cast<std::size_t>(codedWidth) * 3;
  for (int y = 0; y < codedHeight; ++y) {
    std::uint8_t* out = s.rgb.data() + stride * static_cast<std::size_t>(y);
    if (y < s.height) {
      encodeRow8(image.row(y), s.curve, 3, out);
      if (codedWidth > s.width)
        std::memcpy(out + 3 * s.width, out + 3 * (s.width - 1), 3);  // the edge, again
    } else {
      std::memcpy(out, out - stride, stride);  // the last row, again
    }
  }
  int code = av.av_frame_make_writable(s.frame);
  if (code < 0) s.fail("video encoding failed", code);
  const std::uint8_t* source[1] = {s.rgb.data()};
  const int sourceStride[1] = {static_cast<int>(stride)};
  av.sws_scale(s.sws, source, sourceStride, 0, codedHeight, s.frame->data, s.frame->linesize);
  s.frame->pts = s.nextPts++;
  s.encode(s.frame);
  s.file.throwIfFailed();
}

void VideoWriter::finish() {
  State& s = *state_;
  const FfmpegApi& av = s.av;
  s.encode(nullptr);
  const int code = av.av_write_trailer(s.format);
  if (code < 0) s.fail("writing the video failed", code);
  av.avio_flush(s.io);
  s.file.commit();
}

#else

struct VideoWriter::State {};

bool videoSupported() { return false; }

VideoWriter::VideoWriter(const std::string& path, VideoContainer, int, int, const VideoOptions&) {
  throw InputError(
      SourceLocation{path},
      "this lancer was built without FFmpeg (-DLANCER_FFMPEG=OFF): install libavcodec-dev, "
      "libavformat-dev and libswscale-dev (scripts/setup.sh) and rebuild with -DLANCER_FFMPEG=ON, "
      "or write .gif, an animated .png or numbered frames");
}
VideoWriter::~VideoWriter() = default;
void VideoWriter::addFrame(const Image&) {}
void VideoWriter::finish() {}

#endif

}  // namespace lancer
