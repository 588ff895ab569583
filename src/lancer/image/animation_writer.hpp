// Where `lancer animate`, `lancer assemble` and lancer.animate in Python put frames: an animated GIF, an
// animated PNG, an MP4 (H.264) or WebM (VP9) video, or numbered still frames ("turn_%04d.png"), chosen
// by the output's name. Every kind is
// published only when finished: an interrupted or failed animation leaves existing files as they were.
#pragma once

#include <optional>
#include <string>

#include "lancer/image/apng_writer.hpp"
#include "lancer/image/frame_sequence.hpp"
#include "lancer/image/gif_writer.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/image/video_writer.hpp"

namespace lancer {

struct AnimationOutputOptions {
  int frames = 36;
  double fps = 12;
  std::optional<int> loop;  // repeats after the first showing: 0 forever (default), -1 play once
  std::string dither;       // GIF: "ordered" (default), "floyd-steinberg" or "none"
  std::string palette;      // GIF: "global" (default) or "per-frame"
  ImageWriteOptions still;  // the curve and alpha of the scene's still images
  bool transparentBackground = false;
};

// .mp4 or .webm (case-insensitive), else nullopt.
std::optional<VideoContainer> videoContainerFromPath(const std::string& path);

class AnimationWriter {
 public:
  // Checks the name and the options against each other and opens the output now, so that a bad
  // folder or a wrong extension fails before the first frame is rendered. Throws InputError.
  // `checkOnly`: the checks alone, no file (an MPI rank that renders but does not write).
  AnimationWriter(const std::string& output, int width, int height, const AnimationOutputOptions& options,
                  bool checkOnly = false);

  // Numbered frames (a %d in the name), else nullopt.
  const std::optional<FramePattern>& pattern() const { return pattern_; }
  // Numbered .exr frames: they take linear radiance, not display values.
  bool takesRadiance() const { return exrFrames_; }

  // Frames come in order; numbered frames may be any subset (a job-array shard's).
  void addFrame(int frame, const Image& image);
  // After the last frame: publishes the file, or every numbered frame at once.
  void finish();

  // What the writer changes that the user should know, one line each ("" otherwise): what the GIF's
  // whole-1/100-s delays make of the frame rate, a video's padding to even sides or fallback encoder.
  const std::string& frameRateNote() const { return frameRateNote_; }

 private:
  std::optional<FramePattern> pattern_;
  std::optional<GifWriter> gif_;
  std::optional<ApngWriter> apng_;
  std::optional<VideoWriter> video_;
  StagedFrames frames_;
  ImageWriteOptions still_;
  bool exrFrames_ = false;
  std::string frameRateNote_;
};

}  // namespace lancer
