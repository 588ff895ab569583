// Where `lancer animate` and `lancer assemble` put frames: an animated GIF, an animated PNG or numbered
// still frames, chosen by the output name, with the options and defaults both commands share (fps,
// loop, dither, palette), so that assembling rendered frames gives the bytes animate writes directly.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "lancer/image/apng_writer.hpp"
#include "lancer/image/frame_sequence.hpp"
#include "lancer/image/gif_writer.hpp"
#include "lancer/image/image_io.hpp"

namespace lancer::cli {

struct AnimationOutputOptions {
  std::optional<int> loop;  // default: forever
  std::string dither;       // default: ordered
  std::string palette;      // default: global
};

// What the frames are: their size, how many, at what rate, and how stills are encoded (the curve and
// alpha the scene asks for).
struct AnimationFormat {
  int width = 0, height = 0;
  int frames = 0;
  double fps = 12;
  ImageWriteOptions still;
  bool quiet = false;
};

class AnimationOutput {
 public:
  // Checks the options against the output's kind and creates the writer now, so that a bad name or
  // folder fails before any rendering. Throws InputError. `checkOnly`: only the checks, no file (an
  // MPI rank that renders but does not write).
  AnimationOutput(const std::string& output, const AnimationFormat& format,
                  const AnimationOutputOptions& options, bool checkOnly = false);

  // Numbered frames (a %d in the name), else nullopt.
  const std::optional<FramePattern>& pattern() const { return pattern_; }

  // Frames must come in order; numbered frames may be any subset (a shard's).
  void addFrame(int frame, const Image& image);
  // Publishes the file, or every staged numbered frame.
  void finish();

 private:
  std::string output_;
  std::optional<FramePattern> pattern_;
  ImageWriteOptions still_;
  std::optional<GifWriter> gif_;
  std::optional<ApngWriter> apng_;
  StagedFrames frames_;
};

// Refuses a global GIF palette that would keep more than half the machine's memory in frames.
void checkGlobalPaletteMemory(int frames, int width, int height);

}  // namespace lancer::cli
