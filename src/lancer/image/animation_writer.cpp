#include "lancer/image/animation_writer.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "lancer/image/atomic_file.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

// A global palette needs every frame before the first can be written, so the GIF writer keeps them
// all (3 bytes per pixel). Refused up front when that would take more than half the machine's memory.
void checkGlobalPaletteMemory(int frames, int width, int height) {
  const double bytes = 3.0 * frames * width * height;
  const double memory =
      static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE));
  if (memory > 0 && bytes > 0.5 * memory)
    throw InputError(
        SourceLocation{"--palette"},
        fmt::format("a global GIF palette keeps every frame until the end: {} frames of {}x{} need "
                    "{:.1f} GiB, more than half of this machine's {:.1f} GiB; use --palette per-frame "
                    "(frames are then written as they come), fewer frames or a smaller size",
                    frames, width, height, bytes / (1 << 30), memory / (1 << 30)));
}

constexpr const char* kAnimationOutputs =
    "an animation is written as .gif, as an animated .png, as an .mp4 (H.264) or .webm (VP9) video, or as "
    "numbered frames with %04d in the name (frame_%04d.png, .jpg, .webp, .bmp, .ppm or .exr)";

// A video: the frames go to the encoder as they come.
void openVideo(std::optional<VideoWriter>& video, VideoContainer container, const std::string& output,
               int width, int height, const AnimationOutputOptions& options, bool checkOnly,
               std::string& note) {
  if (options.loop)
    throw InputError(
        SourceLocation{"--loop"},
        "--loop applies to an animated .gif or .png; whether a video repeats is its player's choice");
  if (options.still.bitDepth != 8)
    throw InputError(SourceLocation{"--bit-depth"}, "a video holds 8-bit samples: leave --bit-depth at 8");
  if (checkOnly) return;
  VideoOptions videoOptions;
  videoOptions.fps = options.fps;
  videoOptions.curve = options.still.curve;
  videoOptions.metadata = options.still.metadata;
  video.emplace(output, container, width, height, videoOptions);  // fails now on a bad folder
  note = video->note();
}

}  // namespace

std::optional<VideoContainer> videoContainerFromPath(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::nullopt;
  std::string extension = path.substr(dot);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".mp4") return VideoContainer::Mp4;
  if (extension == ".webm") return VideoContainer::Webm;
  return std::nullopt;
}

AnimationWriter::AnimationWriter(const std::string& output, int width, int height,
                                 const AnimationOutputOptions& options, bool checkOnly)
    : pattern_(parseFramePattern(output)), still_(options.still) {
  const std::optional<VideoContainer> video = pattern_ ? std::nullopt : videoContainerFromPath(output);
  if (video && !options.dither.empty())
    throw InputError(SourceLocation{"--dither"}, "--dither applies to an animated .gif only");
  if (video && !options.palette.empty())
    throw InputError(SourceLocation{"--palette"}, "--palette applies to an animated .gif only");
  if (video) {
    openVideo(video_, *video, output, width, height, options, checkOnly, frameRateNote_);
    return;
  }
  ImageFormat format = ImageFormat::Png;
  try {
    format = imageFormatFromPath(pattern_ ? pattern_->name(0) : output);
  } catch (const InputError&) {
    if (pattern_) throw;  // numbered frames: the still formats' message
    throw InputError(SourceLocation{output}, kAnimationOutputs);
  }
  const bool animatedGif = !pattern_ && format == ImageFormat::Gif;
  exrFrames_ = pattern_ && format == ImageFormat::Exr;
  if (!animatedGif && !options.dither.empty())
    throw InputError(SourceLocation{"--dither"}, "--dither applies to an animated .gif only");
  if (!animatedGif && !options.palette.empty())
    throw InputError(SourceLocation{"--palette"}, "--palette applies to an animated .gif only");
  if (pattern_ && options.loop)
    throw InputError(SourceLocation{"--loop"},
                     "--loop applies to an animated .gif or .png, not to numbered frames");
  if (still_.bitDepth != 8 && !(pattern_ && format == ImageFormat::Png))
    throw InputError(SourceLocation{"--bit-depth"},
                     "16-bit samples are written to numbered PNG frames only (-o frame_%04d.png); GIF and "
                     "animated PNG hold 8 bits");
  const int loop = options.loop.value_or(kGifLoopForever);
  if (pattern_) {
    if (checkOnly) return;
    AtomicFileWriter probe(pattern_->name(0));  // a bad folder fails now, not after the first frame
  } else if (format == ImageFormat::Gif) {
    GifOptions gifOptions;
    gifOptions.fps = options.fps;
    gifOptions.loopCount = loop;
    gifOptions.curve = still_.curve;
    gifOptions.palette = options.palette == "per-frame" ? GifPalette::PerFrame : GifPalette::Global;
    gifOptions.dither =
        options.dither == "none"
            ? Dither::None
            : (options.dither == "floyd-steinberg" ? Dither::FloydSteinberg : Dither::Ordered);
    if (gifOptions.palette == GifPalette::Global) checkGlobalPaletteMemory(options.frames, width, height);
    if (std::abs(gifActualFrameRate(options.fps) - options.fps) > 1e-9)
      frameRateNote_ = fmt::format(
          "lancer: GIF delays are whole 1/100 s: {:g} fps plays at {:.4g} fps (a delay of {}/100 s)",
          options.fps, gifActualFrameRate(options.fps), gifFrameDelay(options.fps));
    if (checkOnly) return;
    gif_.emplace(output, width, height, gifOptions);  // fails now on a bad folder
  } else if (format == ImageFormat::Png) {
    ApngOptions apngOptions;
    apngOptions.fps = options.fps;
    // --loop counts repeats after the first showing (GIF's meaning); APNG counts plays.
    apngOptions.loopCount = loop == kGifLoopForever ? 0 : (loop == kGifPlayOnce ? 1 : loop + 1);
    apngOptions.curve = still_.curve;
    apngOptions.alpha = options.transparentBackground;
    if (checkOnly) return;
    apng_.emplace(output, width, height, options.frames, apngOptions);
  } else {
    throw InputError(SourceLocation{output}, kAnimationOutputs);
  }
}

void AnimationWriter::addFrame(int frame, const Image& image) {
  if (gif_) {
    gif_->addFrame(image);
  } else if (apng_) {
    apng_->addFrame(image);
  } else if (video_) {
    video_->addFrame(image);
  } else if (pattern_) {
    frames_.write(pattern_->name(frame), image, still_);
  }
}

void AnimationWriter::finish() {
  if (gif_) gif_->finish();
  if (apng_) apng_->finish();
  if (video_) video_->finish();
  if (pattern_) frames_.publish();
}

}  // namespace lancer
