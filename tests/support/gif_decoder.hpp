// An independent GIF decoder for the writer's tests, built on giflib's DGif* API: it composites the
// frames onto the screen the way a viewer does, so a test compares what people will see.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lancer::test {

struct DecodedGifFrame {
  int delay = -1;  // hundredths; -1 without a Graphic Control Extension
  int left = 0, top = 0, width = 0, height = 0;
  bool localPalette = false;
  std::vector<std::uint8_t> canvas;  // the whole screen after this frame, RGB8
};

struct DecodedGif {
  int width = 0, height = 0;
  bool globalPalette = false;
  std::optional<int> loopCount;  // from a NETSCAPE2.0 block
  std::vector<DecodedGifFrame> frames;
  std::string error;  // empty when decoding worked
};

DecodedGif decodeGif(const std::string& path);

// What a whole decoded GIF should be, apart from its pictures.
struct GifLayout {
  int width = 0, height = 0;
  bool globalPalette = true;     // one palette for all frames, else each frame its own
  std::optional<int> loopCount;  // std::nullopt: plays once (no NETSCAPE2.0 block)
  std::size_t frames = 0;
  int delay = 0;  // of every frame, hundredths
};

// Adds gtest failures where `gif` differs from `layout`: decoded without error, its screen's size,
// its palettes, its loop count, and each frame's delay. A decoding error or another number of frames
// is a fatal failure: call it in ASSERT_NO_FATAL_FAILURE before reading the frames.
void expectGifLayout(const DecodedGif& gif, const GifLayout& layout);

}  // namespace lancer::test
