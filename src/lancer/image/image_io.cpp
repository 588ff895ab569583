#include "lancer/image/image_io.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

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
  if (extension == ".bmp") return ImageFormat::Bmp;
  if (extension == ".ppm") return ImageFormat::Ppm;
  if (extension == ".gif") return ImageFormat::Gif;
  const std::string found = extension.empty() ? "no extension" : fmt::format("'{}'", extension);
  throw InputError(
      SourceLocation{path},
      fmt::format("unknown image format: {}; the supported extensions are {}", found, kImageExtensions));
}

void writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options) {
  switch (imageFormatFromPath(path)) {
    case ImageFormat::Png:
      writePng(path, image, options);
      return;
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
  }
}

}  // namespace lancer
