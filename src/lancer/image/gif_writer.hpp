// Animated GIF output (giflib's EGif* API) with lancer's own palette quantiser and dithering:
// a GIF89a with a NETSCAPE2.0 loop block and one Graphic Control Extension (delay) per frame.
#pragma once

#include <memory>
#include <string>

#include "lancer/image/dither.hpp"
#include "lancer/image/image.hpp"
#include "lancer/image/pixel_encoding.hpp"

namespace lancer {

inline constexpr int kGifLoopForever = 0;
inline constexpr int kGifPlayOnce = -1;  // no NETSCAPE2.0 block at all

enum class GifPalette {
  Global,    // one palette from all frames: no colour flicker on a turntable (the default)
  PerFrame,  // a palette per frame: better colours when frames differ a lot, frames streamed out
};

struct GifOptions {
  double fps = 10;
  // The NETSCAPE2.0 repeat count: 0 = forever, n = n repeats after the first showing (browsers show
  // the animation n + 1 times), kGifPlayOnce = no loop block.
  int loopCount = kGifLoopForever;
  GifPalette palette = GifPalette::Global;
  // Ordered by default: without dithering, 256 colours band visibly on smooth shading, and ordered
  // dither patterns stay put between frames, unlike error diffusion. Frames whose colours all fit
  // in the palette are never dithered.
  Dither dither = Dither::Ordered;
  TransferCurve curve = TransferCurve::Linear;
};

// GIF delays are whole hundredths of a second, and viewers slow delays below 2 down to ~10, so:
// round(100 / fps) clamped to [2, 65535]. fps must be positive.
int gifFrameDelay(double fps);
// The rate the GIF really plays at, 100 / gifFrameDelay(fps): 12 fps becomes 100/8 = 12.5 fps.
double gifActualFrameRate(double fps);

// Takes frames one at a time and writes the file atomically in finish(); destroying the writer
// without finish() leaves no file behind (and any existing file untouched).
// Memory: with a per-frame palette each frame is quantised and written as it arrives and nothing is
// kept. A global palette must see every frame before the first is written, so each frame is kept as
// 8-bit RGB (3 bytes per pixel: 36 frames of 800x600 take 52 MB) while the palette statistics
// accumulate. With a global palette, each frame after the first stores only the rectangle that
// changed (the previous frame stays: disposal "do not dispose"), which shrinks turntables a lot.
// Alpha is ignored: GIF frames are written opaque.
class GifWriter {
 public:
  // Creates the temporary file at once, so a bad output folder fails before any rendering.
  // Throws InputError for a size outside 1..65535, fps <= 0 or a loop count outside -1..65535.
  GifWriter(std::string path, int width, int height, GifOptions options = {});
  ~GifWriter();
  GifWriter(const GifWriter&) = delete;
  GifWriter& operator=(const GifWriter&) = delete;

  // The frame must have the writer's size (std::invalid_argument otherwise).
  void addFrame(const Image& frame);
  // Writes the remaining frames and publishes the file; needs at least one frame. Throws InputError.
  void finish();

  int frameCount() const { return frameCount_; }
  int frameDelay() const;  // hundredths of a second

 private:
  struct Encoder;
  std::unique_ptr<Encoder> encoder_;
  int frameCount_ = 0;
};

}  // namespace lancer
