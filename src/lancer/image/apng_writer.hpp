// Animated PNG (APNG) output: lossless frames with exact timing. Debian's libpng has no APNG
// support, so the chunks are written here by the specification, with zlib for deflate and CRCs.
#pragma once

#include <memory>
#include <string>

#include "lancer/image/image.hpp"
#include "lancer/image/pixel_encoding.hpp"

namespace lancer {

struct ApngOptions {
  double fps = 10;
  int loopCount = 0;  // acTL num_plays: 0 = forever, n = play n times
  TransferCurve curve = TransferCurve::Linear;
  bool alpha = false;  // RGBA instead of RGB
};

// The frame delay as the fraction num/den seconds that fcTL stores (both 16-bit): exact 1/fps for
// integral rates up to 65535, otherwise milliseconds rounded (never 0).
struct ApngDelay {
  int numerator = 1, denominator = 10;
};
ApngDelay apngFrameDelay(double fps);

// Writes frames as they arrive (the frame count is needed up front for the acTL chunk) and publishes
// the file atomically in finish(); destroying the writer without finish() leaves any existing file
// untouched. The first frame is the PNG's default image, so viewers without APNG show frame 0.
// https://wiki.mozilla.org/APNG_Specification
class ApngWriter {
 public:
  // Creates the temporary file at once, so a bad output folder fails before any rendering.
  // Throws InputError for a size outside 1..kMaxImageSide, frameCount < 1, fps <= 0 or a loop count
  // outside 0..65535.
  ApngWriter(std::string path, int width, int height, int frameCount, ApngOptions options = {});
  ~ApngWriter();
  ApngWriter(const ApngWriter&) = delete;
  ApngWriter& operator=(const ApngWriter&) = delete;

  // The frame must have the writer's size (std::invalid_argument otherwise); at most frameCount frames.
  void addFrame(const Image& frame);
  // Publishes the file once all frameCount frames were added. Throws InputError on I/O failure.
  void finish();

 private:
  struct Encoder;
  std::unique_ptr<Encoder> encoder_;
};

}  // namespace lancer
