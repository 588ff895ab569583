// Helpers shared by the image tests: scratch folders, file bytes, and an independent GIF decoder
// built on giflib's DGif* API that composites frames the way a viewer does.
#pragma once

#include <gif_lib.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "lancer/image/image.hpp"
#include "lancer/image/pixel_encoding.hpp"

namespace lancer::test {

// A fresh folder under /tmp, removed with everything in it at the end of the test.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "lancer-image-test-XXXXXX").string();
    path_ = ::mkdtemp(pattern.data());
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all, ignored);
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path_))
      names.push_back(entry.path().filename());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  std::filesystem::path path_;
};

inline std::vector<std::uint8_t> readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

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

inline std::optional<int> netscapeLoop(const ExtensionBlock* blocks, int count) {
  for (int i = 0; i + 1 < count; ++i) {
    if (blocks[i].Function == APPLICATION_EXT_FUNC_CODE && blocks[i].ByteCount == 11 &&
        std::string(reinterpret_cast<const char*>(blocks[i].Bytes), 11) == "NETSCAPE2.0" &&
        blocks[i + 1].Function == CONTINUE_EXT_FUNC_CODE && blocks[i + 1].ByteCount == 3 &&
        blocks[i + 1].Bytes[0] == 1) {
      return blocks[i + 1].Bytes[1] | (blocks[i + 1].Bytes[2] << 8);
    }
  }
  return std::nullopt;
}

inline DecodedGif decodeGif(const std::string& path) {
  DecodedGif out;
  int error = 0;
  GifFileType* gif = DGifOpenFileName(path.c_str(), &error);
  if (gif == nullptr) {
    out.error = GifErrorString(error);
    return out;
  }
  if (DGifSlurp(gif) == GIF_ERROR) {
    out.error = GifErrorString(gif->Error);
    DGifCloseFile(gif, &error);
    return out;
  }
  out.width = gif->SWidth;
  out.height = gif->SHeight;
  out.globalPalette = gif->SColorMap != nullptr;
  if (gif->ImageCount > 0) {
    out.loopCount =
        netscapeLoop(gif->SavedImages[0].ExtensionBlocks, gif->SavedImages[0].ExtensionBlockCount);
  }
  std::vector<std::uint8_t> canvas(static_cast<std::size_t>(out.width) * out.height * 3, 0);
  for (int i = 0; i < gif->ImageCount; ++i) {
    const SavedImage& image = gif->SavedImages[i];
    DecodedGifFrame frame;
    GraphicsControlBlock control;
    if (DGifSavedExtensionToGCB(gif, i, &control) == GIF_OK) frame.delay = control.DelayTime;
    frame.left = image.ImageDesc.Left;
    frame.top = image.ImageDesc.Top;
    frame.width = image.ImageDesc.Width;
    frame.height = image.ImageDesc.Height;
    frame.localPalette = image.ImageDesc.ColorMap != nullptr;
    const ColorMapObject* map =
        image.ImageDesc.ColorMap != nullptr ? image.ImageDesc.ColorMap : gif->SColorMap;
    for (int y = 0; y < frame.height; ++y) {
      for (int x = 0; x < frame.width; ++x) {
        const GifByteType index = image.RasterBits[y * frame.width + x];
        const GifColorType colour = map->Colors[index];
        const std::size_t at = (static_cast<std::size_t>(frame.top + y) * out.width + frame.left + x) * 3;
        canvas[at] = colour.Red;
        canvas[at + 1] = colour.Green;
        canvas[at + 2] = colour.Blue;
      }
    }
    frame.canvas = canvas;
    out.frames.push_back(std::move(frame));
  }
  DGifCloseFile(gif, &error);
  return out;
}

// Mean and largest absolute difference between 8-bit samples.
struct SampleError {
  double mean = 0;
  int max = 0;
};

inline SampleError sampleError(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  SampleError e;
  if (a.size() != b.size() || a.empty()) return {1e9, 255};
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const int d = std::abs(int{a[i]} - int{b[i]});
    sum += d;
    e.max = std::max(e.max, d);
  }
  e.mean = sum / static_cast<double>(a.size());
  return e;
}

// A smooth-shaded test picture: a lit sphere over a vertical gradient, shifted by `phase` (0..1),
// with far more than 256 colours, like a render.
inline Image shadedSphere(int width, int height, float phase) {
  Image image(width, height);
  const float cx = width * (0.3f + 0.4f * phase), cy = height * 0.5f, radius = height * 0.35f;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float dx = (x + 0.5f - cx) / radius, dy = (y + 0.5f - cy) / radius;
      const float r2 = dx * dx + dy * dy;
      if (r2 < 1) {
        const float nz = std::sqrt(1 - r2);
        const float diffuse = std::max(0.0f, -0.4f * dx - 0.5f * dy + 0.77f * nz);
        image.at(x, y) = {0.1f + 0.8f * diffuse, 0.08f + 0.5f * diffuse, 0.05f + 0.3f * diffuse, 1};
      } else {
        const float t = static_cast<float>(y) / static_cast<float>(height);
        image.at(x, y) = {0.2f * t, 0.25f * t, 0.5f * t + 0.1f, 1};
      }
    }
  }
  return image;
}

}  // namespace lancer::test
