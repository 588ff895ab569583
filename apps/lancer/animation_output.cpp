#include "animation_output.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "lancer/image/atomic_file.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer::cli {

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

AnimationOutput::AnimationOutput(const std::string& output, const AnimationFormat& format,
                                 const AnimationOutputOptions& options, bool checkOnly)
    : output_(output), pattern_(parseFramePattern(output)), still_(format.still) {
  const ImageFormat imageFormat = imageFormatFromPath(pattern_ ? pattern_->name(0) : output);
  const bool animatedGif = !pattern_ && imageFormat == ImageFormat::Gif;
  if (!animatedGif && !options.dither.empty())
    throw InputError(SourceLocation{"--dither"}, "--dither applies to an animated .gif only");
  if (!animatedGif && !options.palette.empty())
    throw InputError(SourceLocation{"--palette"}, "--palette applies to an animated .gif only");
  if (pattern_ && options.loop)
    throw InputError(SourceLocation{"--loop"},
                     "--loop applies to an animated .gif or .png, not to numbered frames");
  const int loop = options.loop.value_or(kGifLoopForever);
  if (pattern_) {
    if (checkOnly) return;
    AtomicFileWriter probe(pattern_->name(0));  // a bad folder fails now, not after the first frame
  } else if (imageFormat == ImageFormat::Gif) {
    GifOptions gifOptions;
    gifOptions.fps = format.fps;
    gifOptions.loopCount = loop;
    gifOptions.curve = format.still.curve;
    gifOptions.palette = options.palette == "per-frame" ? GifPalette::PerFrame : GifPalette::Global;
    gifOptions.dither =
        options.dither == "none"
            ? Dither::None
            : (options.dither == "floyd-steinberg" ? Dither::FloydSteinberg : Dither::Ordered);
    if (gifOptions.palette == GifPalette::Global)
      checkGlobalPaletteMemory(format.frames, format.width, format.height);
    if (checkOnly) return;
    gif_.emplace(output, format.width, format.height, gifOptions);  // fails now on a bad folder
    if (!format.quiet && std::abs(gifActualFrameRate(format.fps) - format.fps) > 1e-9)
      std::fprintf(stderr,
                   "lancer: GIF delays are whole 1/100 s: %g fps plays at %.4g fps (a delay of %d/100 s)\n",
                   format.fps, gifActualFrameRate(format.fps), gifFrameDelay(format.fps));
  } else if (imageFormat == ImageFormat::Png) {
    ApngOptions apngOptions;
    apngOptions.fps = format.fps;
    // --loop counts repeats after the first showing (GIF's meaning); APNG counts plays.
    apngOptions.loopCount = loop == kGifLoopForever ? 0 : (loop == kGifPlayOnce ? 1 : loop + 1);
    apngOptions.curve = format.still.curve;
    apngOptions.alpha = format.still.alpha == AlphaChannel::Always;
    if (checkOnly) return;
    apng_.emplace(output, format.width, format.height, format.frames, apngOptions);
  } else {
    throw InputError(
        SourceLocation{output},
        "an animation is written as .gif, as an animated .png, or as numbered frames with %04d in the "
        "name (frame_%04d.png, .bmp or .ppm)");
  }
}

void AnimationOutput::addFrame(int frame, const Image& image) {
  if (gif_) {
    gif_->addFrame(image);
  } else if (apng_) {
    apng_->addFrame(image);
  } else {
    frames_.write(pattern_->name(frame), image, still_);
  }
}

void AnimationOutput::finish() {
  if (gif_) gif_->finish();
  if (apng_) apng_->finish();
  if (pattern_) frames_.publish();
}

}  // namespace lancer::cli
