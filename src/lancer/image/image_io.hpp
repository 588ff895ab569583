// Reading and writing still images: PNG (libpng), JPEG (libjpeg-turbo), WebP (libwebp), BMP and PPM
// (written by lancer), a single-frame GIF and OpenEXR (exr_io.hpp); the format follows the file
// extension. Every write is atomic (see atomic_file.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lancer/image/gif_writer.hpp"
#include "lancer/image/image.hpp"
#include "lancer/image/image_metadata.hpp"
#include "lancer/image/pixel_encoding.hpp"

namespace lancer {

enum class ImageFormat { Png, Jpeg, Webp, Bmp, Ppm, Gif, Exr };

// "Auto" stores alpha only when some pixel is not opaque; PNG and WebP hold alpha, the other formats drop
// it (a transparent render's colour already holds the background colour where nothing was hit).
enum class AlphaChannel { Auto, Always, Never };

struct ImageWriteOptions {
  TransferCurve curve = TransferCurve::Linear;
  AlphaChannel alpha = AlphaChannel::Auto;
  Dither dither = Dither::Ordered;     // .gif only (256 colours; see GifOptions)
  int bitDepth = 8;                    // 8, or 16 for PNG (other formats refuse 16 with an InputError)
  int quality = kDefaultImageQuality;  // .jpg and lossy .webp: 1 to 100
  bool lossless = false;               // .webp: lossless instead of `quality`
  // DPI (PNG pHYs, JPEG JFIF density, WebP EXIF) and provenance (PNG tEXt, JPEG COM, WebP EXIF, EXR
  // header attributes); nothing when empty.
  ImageMetadata metadata;
};

// The extensions writeImage accepts, for messages and --help.
inline constexpr const char* kImageExtensions = ".png, .jpg, .jpeg, .webp, .bmp, .ppm, .gif, .exr";

// By extension, case-insensitive. Throws InputError naming the file and the supported extensions.
ImageFormat imageFormatFromPath(const std::string& path);

// Throws InputError naming `path` unless `bitDepth` is 8, or 16 for a PNG.
void requireBitDepth(const std::string& path, ImageFormat format, int bitDepth);

// Throws InputError naming `path` when the format cannot hold a picture this size (WebP: 16383 pixels
// a side; JPEG: 65500), so that a render is refused before it starts.
void requireImageSize(const std::string& path, ImageFormat format, int width, int height);

// Writes `image` in the format its extension names; throws InputError on a bad path or I/O failure.
void writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options = {});

void writePng(const std::string& path, const Image& image, const ImageWriteOptions& options = {});
// A PNG of samples already encoded: rows top to bottom, `channels` (3 or 4) bytes per pixel;
// `srgbChunk` marks them as sRGB-encoded (what writePng does for TransferCurve::Srgb).
void writePng8(const std::string& path, int width, int height, int channels, bool srgbChunk,
               const std::uint8_t* samples, const ImageMetadata& metadata = {});
// A PNG of 8- or 16-bit samples (16: two bytes each, big-endian, as PNG stores them). The metadata goes
// into pHYs (DPI) and tEXt chunks ("Software", "Comment": the command), before the pixels.
void writePngSamples(const std::string& path, int width, int height, int channels, bool srgbChunk,
                     int bitDepth, const std::uint8_t* samples, const ImageMetadata& metadata = {});
// Any format by extension from 8-bit samples encoded with `options.curve`: exactly the bytes writeImage
// writes for the image they came from (with AlphaChannel::Always for 4 channels, Never for 3).
void writeImage8(const std::string& path, int width, int height, int channels, const std::uint8_t* samples,
                 const ImageWriteOptions& options = {});
// JPEG (baseline, 4:2:0, JFIF density in DPI, the provenance in a COM marker) from 3 or 4 channels of
// 8-bit samples (alpha dropped); `quality` 1 to 100.
void writeJpeg8(const std::string& path, int width, int height, int channels, const std::uint8_t* samples,
                int quality, const ImageMetadata& metadata = {});
// WebP, lossy at `quality` or lossless, with alpha when channels is 4; DPI and provenance in an EXIF chunk.
void writeWebp8(const std::string& path, int width, int height, int channels, const std::uint8_t* samples,
                int quality, bool lossless, const ImageMetadata& metadata = {});
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
