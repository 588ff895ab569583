// MP4 (H.264) and WebM (VP9) animations through FFmpeg's libraries: libswscale turns each frame's
// sRGB samples into 4:2:0 YUV (BT.709), libavcodec encodes it as it comes (no frame is kept), and
// libavformat muxes the packets into a file written atomically (atomic_file.hpp).
#pragma once

#include <memory>
#include <string>

#include "lancer/image/image.hpp"
#include "lancer/image/image_metadata.hpp"
#include "lancer/image/pixel_encoding.hpp"

namespace lancer {

enum class VideoContainer { Mp4, Webm };

// False when this lancer was built without FFmpeg (-DLANCER_FFMPEG=OFF): VideoWriter then throws.
bool videoSupported();

struct VideoOptions {
  double fps = 12;
  TransferCurve curve = TransferCurve::Srgb;  // how the frames' values become 8-bit samples
  ImageMetadata metadata;                     // software and command: the file's "comment" tag
};

class VideoWriter {
 public:
  // Chooses the encoder (MP4: libx264, else another H.264 encoder, else MPEG-4 part 2 with a note;
  // WebM: libvpx-vp9), creates the temporary file and writes the header, so a bad folder or a missing
  // encoder fails before the first frame. 4:2:0 needs even sides: an MP4 of odd width or height
  // gets one more column or row, a copy of the last (note() says so). Throws InputError naming `path`.
  VideoWriter(const std::string& path, VideoContainer container, int width, int height,
              const VideoOptions& options);
  // Without finish(): the temporary file is removed and an existing file is untouched.
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // The next frame (display values: the alpha channel is dropped). Throws InputError.
  void addFrame(const Image& image);
  // Flushes the encoder, writes the trailer and publishes the file. Throws InputError.
  void finish();

  // What the writer changed that the user should know (padding, a fallback encoder); "" otherwise.
  const std::string& note() const { return note_; }

 private:
  struct State;
  std::unique_ptr<State> state_;
  std::string note_;
};

}  // namespace lancer
