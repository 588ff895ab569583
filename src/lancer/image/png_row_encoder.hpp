// libpng's row interface behind a C++ class, for writers that hand rows over one at a time
// (ImageRowWriter). Internal to the image module: the header and deflate settings are those of
// writePng, so both paths give the same bytes.
#pragma once

#include <cstddef>
#include <cstdint>

#include "lancer/image/image_metadata.hpp"

struct png_struct_def;
struct png_info_def;

namespace lancer {

class AtomicFileWriter;

inline constexpr std::size_t kPngErrorTextSize = 256;  // libpng's message, truncated

class PngRowEncoder {
 public:
  // Writes the signature and the header chunks (IHDR; sRGB, gAMA and cHRM when `srgbChunk`; pHYs and
  // text from `metadata`) to `file`. channels is 3 (RGB) or 4 (RGBA), of `bitDepth` 8 or 16 bits each (16:
  // big-endian samples, as PNG stores them). Throws InputError naming the file.
  PngRowEncoder(AtomicFileWriter& file, int width, int height, int channels, bool srgbChunk, int bitDepth = 8,
                const ImageMetadata& metadata = {});
  ~PngRowEncoder();
  PngRowEncoder(const PngRowEncoder&) = delete;
  PngRowEncoder& operator=(const PngRowEncoder&) = delete;

  // One row of width * channels samples (bytes: times bitDepth / 8); rows go top to bottom. Throws
  // InputError.
  void writeRow(const std::uint8_t* samples);
  // After the last row: the final IDAT data and IEND. Throws InputError.
  void finish();

 private:
  // libpng reports errors by longjmp: these hold the setjmp and only trivially destructible locals,
  // and return false (with errorText_ set) when libpng failed.
  bool start(int width, int height, int channels, bool srgbChunk, int bitDepth,
             const ImageMetadata& metadata);
  bool row(const std::uint8_t* samples);
  bool end();
  void destroy() noexcept;
  // Throws the failed write's InputError, or one with libpng's message.
  [[noreturn]] void fail();

  AtomicFileWriter& file_;
  png_struct_def* png_ = nullptr;
  png_info_def* info_ = nullptr;
  char errorText_[kPngErrorTextSize] = {};
};

}  // namespace lancer
