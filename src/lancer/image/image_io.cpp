#include "lancer/image/image_io.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "lancer/image/exr_io.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

ImageFormat imageFormatFromPath(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  std::string extension;
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) extension = path.substr(dot);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".png") return ImageFormat::Png;
  if (extension == ".jpg" || extension == ".jpeg") return ImageFormat::Jpeg;
  if (extension == ".webp") return ImageFormat::Webp;
  if (extension == ".bmp") return ImageFormat::Bmp;
  if (extension == ".ppm") return ImageFormat::Ppm;
  if (extension == ".gif") return ImageFormat::Gif;
  if (extension == ".exr") return ImageFormat::Exr;
  const std::string found = extension.empty() ? "no extension" : fmt::format("'{}'", extension);
  throw InputError(
      SourceLocation{path},
      fmt::format("unknown image format: {}; the supported extensions are {}", found, kImageExtensions));
}

void writeImage8(const std::string& path, int width, int height, int channels, const std::uint8_t* samples,
                 const ImageWriteOptions& options) {
  const ImageFormat format = imageFormatFromPath(path);
  switch (format) {
    case ImageFormat::Png:
      writePng8(path, width, height, channels, options.curve == TransferCurve::Srgb, samples,
                options.metadata);
      return;
    case ImageFormat::Jpeg:
      writeJpeg8(path, width, height, channels, samples, options.quality, options.metadata);
      return;
    case ImageFormat::Webp:
      writeWebp8(path, width, height, channels, samples, options.quality, options.lossless, options.metadata);
      return;
    default:
      break;
  }
  // The other writers encode from float: linear decoding gives back each byte exactly (v / 255 encodes
  // as round(255 * v / 255) = v), and none of them marks the curve in the file.
  Image image(width, height);
  const std::size_t stride = static_cast<std::size_t>(channels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::uint8_t* p = samples + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                         static_cast<std::size_t>(x)) *
                                            stride;
      image.at(x, y) =
          Rgba{decode8(p[0]), decode8(p[1]), decode8(p[2]), channels == 4 ? decode8(p[3]) : 1.0f};
    }
  ImageWriteOptions linear = options;
  linear.curve = TransferCurve::Linear;
  linear.alpha = channels == 4 ? AlphaChannel::Always : AlphaChannel::Never;
  writeImage(path, image, linear);
}

void requireBitDepth(const std::string& path, ImageFormat format, int bitDepth) {
  if (format == ImageFormat::Exr) return;  // always 32-bit float
  if (bitDepth == 8 || (bitDepth == 16 && format == ImageFormat::Png)) return;
  if (bitDepth == 16)
    throw InputError(SourceLocation{path},
                     "16-bit samples are written to PNG only: give -o NAME.png, or leave --bit-depth at 8");
  throw InputError(SourceLocation{path}, fmt::format("bit depth {} is not supported: use 8 or 16", bitDepth));
}

void requireImageSize(const std::string& path, ImageFormat format, int width, int height) {
  // WEBP_MAX_DIMENSION (libwebp's encode.h) and JPEG_MAX_DIMENSION (libjpeg's jmorecfg.h).
  const int limit =
      format == ImageFormat::Webp ? 16383 : (format == ImageFormat::Jpeg ? 65500 : kMaxImageSide);
  if (width > limit || height > limit)
    throw InputError(SourceLocation{path},
                     fmt::format("{}x{} is too large for {}: at most {} pixels a side; write a .png", width,
                                 height, format == ImageFormat::Webp ? "WebP" : "JPEG", limit));
}

void writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options) {
  const ImageFormat format = imageFormatFromPath(path);
  requireBitDepth(path, format, options.bitDepth);
  switch (format) {
    case ImageFormat::Png:
      writePng(path, image, options);
      return;
    case ImageFormat::Jpeg: {
      if (image.empty()) throw InputError(SourceLocation{path}, "cannot write an empty (0-pixel) JPEG");
      const std::vector<std::uint8_t> samples = encodeImage8(image, options.curve, 3);
      writeJpeg8(path, image.width(), image.height(), 3, samples.data(), options.quality, options.metadata);
      return;
    }
    case ImageFormat::Webp: {
      if (image.empty()) throw InputError(SourceLocation{path}, "cannot write an empty (0-pixel) WebP");
      const bool alpha = options.alpha == AlphaChannel::Always ||
                         (options.alpha == AlphaChannel::Auto && image.hasTransparency());
      const int channels = alpha ? 4 : 3;
      const std::vector<std::uint8_t> samples = encodeImage8(image, options.curve, channels);
      writeWebp8(path, image.width(), image.height(), channels, samples.data(), options.quality,
                 options.lossless, options.metadata);
      return;
    }
    case ImageFormat::Bmp:
      writeBmp(path, image, options.curve);
      return;
    case ImageFormat::Ppm:
      writePpm(path, image, options.curve);
      return;
    case ImageFormat::Gif: {
      GifOptions gif;
      gif.curve = options.curve;
      gif.dither = options.dither;
      gif.loopCount = kGifPlayOnce;
      GifWriter writer(path, image.width(), image.height(), gif);
      writer.addFrame(image);
      writer.finish();
      return;
    }
    case ImageFormat::Exr:
      writeExr(path, image, {}, options.metadata);  // linear radiance: the curve does not apply
      return;
  }
}

}  // namespace lancer
