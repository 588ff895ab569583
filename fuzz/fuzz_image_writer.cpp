// libFuzzer target: the image writers and their options. The input picks a file name (so the format
// comes from an arbitrary extension), the transfer curve, alpha and dither choices, the GIF frame
// rate, loop count and palette mode, a small image size and raw float pixels (NaN, inf, negatives
// included). Mode 3 instead hands the bytes to readPng, the only image reader. Files go to a private
// temporary folder that must be empty again after every input: a left-over temporary file is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "lancer/image/gif_writer.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/util/input_error.hpp"

namespace {

std::string gFolder;

// Consumes the fuzz input front to back; past the end every read yields zeros.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  template <class T>
  T raw() {
    unsigned char bytes[sizeof(T)] = {};
    for (unsigned char& b : bytes) b = byte();
    T value;
    std::memcpy(&value, bytes, sizeof value);
    return value;
  }
  bool done() const { return pos_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

void expectFolderEmpty() {
  if (!std::filesystem::is_empty(gFolder)) {
    for (const auto& entry : std::filesystem::directory_iterator(gFolder))
      std::fprintf(stderr, "left behind: %s\n", entry.path().c_str());
    std::abort();
  }
}

void clearFolder() {
  for (const auto& entry : std::filesystem::directory_iterator(gFolder))
    std::filesystem::remove(entry.path());
}

void fuzzReadPng(const std::uint8_t* data, std::size_t size) {
  const std::string path = gFolder + "/in.png";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) std::abort();
  if (size != 0 && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
  try {
    const lancer::Image image = lancer::readPng(path, lancer::TransferCurve::Srgb);
    (void)image;
  } catch (const lancer::InputError&) {
  }
  std::filesystem::remove(path);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp != nullptr ? tmp : "/tmp") + "/lancer-fuzz-image-XXXXXX";
  if (mkdtemp(pattern.data()) == nullptr) std::abort();
  gFolder = pattern;
  std::atexit([] {
    std::error_code ignored;
    std::filesystem::remove_all(gFolder, ignored);
  });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  const int mode = in.byte() % 4;
  if (mode == 3) {
    fuzzReadPng(data + 1, size == 0 ? 0 : size - 1);
    return 0;
  }

  // A file name of up to 8 bytes, without '/' or NUL (the folder is fixed).
  std::string name;
  const int nameLength = in.byte() % 9;
  for (int i = 0; i < nameLength; ++i) {
    const char c = static_cast<char>(in.byte());
    if (c != '/' && c != '\0') name += c;
  }
  if (name.empty() || name == "." || name == "..") name = "x";
  const std::string path = gFolder + "/" + name;

  const std::uint8_t flags = in.byte();
  lancer::ImageWriteOptions options;
  options.curve = (flags & 1) != 0 ? lancer::TransferCurve::Srgb : lancer::TransferCurve::Linear;
  options.alpha = static_cast<lancer::AlphaChannel>(((flags >> 1) & 3) % 3);
  options.dither = static_cast<lancer::Dither>(((flags >> 3) & 3) % 3);
  const int width = in.byte() % 17;
  const int height = in.byte() % 17;

  lancer::Image image(width, height);
  for (lancer::Rgba& pixel : image.pixels()) pixel = in.raw<lancer::Rgba>();

  try {
    if (mode == 0) {
      lancer::writeImage(path, image, options);
      if (lancer::imageFormatFromPath(path) == lancer::ImageFormat::Png) {
        const lancer::Image back = lancer::readPng(path);
        if (back.width() != width || back.height() != height) std::abort();
      }
    } else if (mode == 1) {
      // The in-memory encoders: the file size is fixed by the header they write.
      const std::size_t bmpRow = (3 * static_cast<std::size_t>(width) + 3) / 4 * 4;
      if (lancer::encodeBmp(image, options.curve).size() != 54 + bmpRow * static_cast<std::size_t>(height))
        std::abort();
      (void)lancer::encodePpm(image, options.curve);
    } else {
      lancer::GifOptions gif;
      gif.fps = in.raw<double>();
      gif.loopCount = in.raw<std::int32_t>();
      gif.palette = (flags & 32) != 0 ? lancer::GifPalette::PerFrame : lancer::GifPalette::Global;
      gif.dither = options.dither;
      gif.curve = options.curve;
      const int frames = 1 + (flags >> 6);
      lancer::GifWriter writer(path + ".gif", width, height, gif);
      for (int i = 0; i < frames; ++i) {
        for (lancer::Rgba& pixel : image.pixels()) pixel.r += 0.25f * static_cast<float>(i);
        writer.addFrame(image);
      }
      writer.finish();
    }
  } catch (const lancer::InputError&) {
    expectFolderEmpty();  // a failed write leaves nothing behind
  }
  clearFolder();
  return 0;
}
