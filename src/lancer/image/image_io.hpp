// Reading and writing still images: PNG (libpng), BMP and PPM (written by lancer), a single-frame
// GIF and OpenEXR (exr_io.hpp); the format follows the file extension. Every write is atomic (see
// atomic_file.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lancer/image/gif_writer.hpp"
#include "lancer/image/image.hpp"
#include "lancer/image/pixel_encoding.hpp"

namespace lancer {

enum class ImageFormat { Png, Bmp, Ppm, Gif, Exr };

// "Auto" stores alpha only when some pixel is not opaque; PNG is the only format with alpha.
enum class AlphaChannel { Auto, Always, Never };

struct ImageWriteOptions {
  TransferCurve curve = TransferCurve::Linear;
  AlphaChannel alpha = AlphaChannel::Auto;
  Dither dither = Dither::Ordered;  // .gif only (256 colours; see GifOptions)
  int bitDepth = 8;                 // 8, or 16 for PNG (other formats refuse 16 with an InputError)
};

// The extensions writeImage accepts, for messages and --help: ".png, .bmp, .ppm, .gif, .exr".
inline constexpr const char* kImageExtensions = ".png, .bmp, .ppm, .gif, .exr";

// By extension, case-insensitive. Throws InputError naming the file and the supported extensions.
ImageFormat imageFormatFromPath(const std::string& path);

// Throws InputError naming `path` unless `bitDepth` is 8, or 16 for a PNG.
void requireBitDepth(const std::string& path, ImageFormat format, int bitDepth);

// Writes `image` in the format its extension names; throws InputError on a bad path or I/O failure.
void writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options = {});

void writePng(const std::string& path, const Image& image, const ImageWriteOptions& options = {});
// A PNG of samples already encoded: rows top to bottom, `channels` (3 or 4) bytes per pixel;
// `srgbChunk` marks them as sRGB-encoded (what writePng does for TransferCurve::Srgb).
void writePng8(const std::string& path, int width, int height, int channels, bool srgbChunk,
               const std::uint8_t* samples);
// A PNG of 8- or 16-bit samples (16: two bytes each, big-endian, as PNG stores them).
void writePngSamples(const std::string& path, int width, int height, int channels, bool srgbChunk,
                     int bitDepth, const std::uint8_t* samples);
// Any format by extension from 8-bit samples encoded with `curve`: exactly the bytes writeImage writes
// for the image they came from (with AlphaChannel::Always for 4 channels, Never for 3).
void writeImage8(const std::string& path, int width, int height, int channels, TransferCurve curve,
                 const std::uint8_t* samples);
void writeBmp(const std::string& path, const Image& image, TransferCurve curve = TransferCurve::Linear);
void writePpm(const std::string& path, const Image& image, TransferCurve curve = TransferCurve::Linear);

// The complete files in memory (what writeBmp / writePpm store).
// BMP: 24-bit BI_RGB, bottom-up rows of BGR padded to 4 bytes; alpha is dropped.
std::vector<std::uint8_t> encodeBmp(const Image& image, TransferCurve curve = TransferCurve::Linear);
// PPM: binary P6, maxval 255; alpha is dropped.
std::vector<std::uint8_t> encodePpm(const Image& image, TransferCurve curve = TransferCurve::Linear);

// What a PNG's header says about how it was written: an alpha channel (or tRNS), an sRGB chunk.
struct PngDescription {
  bool alpha = false;
  bool srgb = false;
};

// Any PNG (palette, grey, 16-bit, interlaced) as 8-bit RGBA decoded with `curve`; `description`, when
// given, receives what the header says. Throws InputError for unreadable, non-PNG, corrupt or
// oversized (> 2^26 pixels) files.
Image readPng(const std::string& path, TransferCurve curve = TransferCurve::Linear,
              PngDescription* description = nullptr);
// The same with every sample of 16 bits kept (8-bit files widened): v / 65535 decoded with `curve`.
Image readPng16(const std::string& path, TransferCurve curve = TransferCurve::Linear);

}  // namespace lancer
