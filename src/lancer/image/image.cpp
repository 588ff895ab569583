#include "lancer/image/image.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "lancer/image/pixel_encoding.hpp"

namespace lancer {

Image::Image(int width, int height, Rgba fill) : width_(width), height_(height) {
  if (width < 0 || height < 0 || width > kMaxImageSide || height > kMaxImageSide) {
    throw std::invalid_argument(fmt::format("Image size {}x{} outside 0..{} (callers check user sizes)",
                                            width, height, kMaxImageSide));
  }
  pixels_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill);
}

void Image::fill(const Rgba& value) { std::fill(pixels_.begin(), pixels_.end(), value); }

void Image::pasteTile(const Image& tile, int x0, int y0) {
  if (x0 < 0 || y0 < 0 || x0 + tile.width() > width_ || y0 + tile.height() > height_) {
    throw std::invalid_argument(fmt::format("tile {}x{} at ({}, {}) outside the {}x{} image", tile.width(),
                                            tile.height(), x0, y0, width_, height_));
  }
  for (int y = 0; y < tile.height(); ++y) {
    std::span<const Rgba> source = tile.row(y);
    std::copy(source.begin(), source.end(), pixels_.begin() + static_cast<std::ptrdiff_t>(index(x0, y0 + y)));
  }
}

Image Image::crop(int x0, int y0, int width, int height) const {
  if (x0 < 0 || y0 < 0 || width < 0 || height < 0 || x0 + width > width_ || y0 + height > height_) {
    throw std::invalid_argument(fmt::format("crop {}x{} at ({}, {}) outside the {}x{} image", width, height,
                                            x0, y0, width_, height_));
  }
  Image out(width, height);
  for (int y = 0; y < height; ++y) {
    std::span<const Rgba> source =
        row(y0 + y).subspan(static_cast<std::size_t>(x0), static_cast<std::size_t>(width));
    std::copy(source.begin(), source.end(), out.row(y).begin());
  }
  return out;
}

bool Image::hasTransparency() const {
  return std::any_of(pixels_.begin(), pixels_.end(), [](const Rgba& p) { return encode8(p.a) < 255; });
}

}  // namespace lancer
