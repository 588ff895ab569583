// Numbered still frames of `lancer animate` ("turn_%04d.png"): the name pattern, and publishing all
// frames together so that an interrupted or failed animation leaves existing frames untouched.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lancer/image/image_io.hpp"

namespace lancer {

// A frame-sequence name such as "frames/turn_%04d.png": exactly one %d (optionally %0Nd), no other %.
struct FramePattern {
  std::string prefix, suffix;
  int width = 0;

  std::string name(int frame) const;
};

// nullopt when the path has no '%'; InputError for a malformed pattern.
std::optional<FramePattern> parseFramePattern(const std::string& path);

// Whether `path` holds a complete image of width x height (PNG decoded; BMP and PPM by their exact
// size), so `--skip-existing` need not render it again. Atomic writes mean a half-written frame
// cannot exist, but a frame from a render of another size can.
bool completeFrameExists(const std::string& path, int width, int height);

// Each frame (or a legend sheet) is written (atomically) to a hidden file beside its target,
// ".lancer-PID-NAME", as soon as it is rendered; publish() renames them all into place at the end. Destroying
// the object before publish() (Ctrl-C, an error) removes the hidden files, and existing frames stay as they
// were.
class StagedFrames {
 public:
  StagedFrames() = default;
  ~StagedFrames();
  StagedFrames(const StagedFrames&) = delete;
  StagedFrames& operator=(const StagedFrames&) = delete;

  // Writes the frame under a hidden name beside its target (.lancer-PID-NAME). The first write into a
  // folder removes the hidden frames a killed run left there (a PID no process has any more).
  void write(const std::string& target, const Image& image, const ImageWriteOptions& options);
  // Renames every staged frame over its target; throws InputError if a rename fails.
  void publish();

 private:
  std::vector<std::pair<std::string, std::string>> staged_;  // (hidden file, target)
  std::vector<std::string> cleanedFolders_;
};

}  // namespace lancer
