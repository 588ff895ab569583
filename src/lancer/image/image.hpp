// Images of linear floating-point RGBA as the renderer produces them, before any 8-bit encoding.
// Rows run top to bottom (y = 0 is the top row), pixels left to right, as in PNG, PPM and GIF.
// Map: docs/architecture.md (the path of a ray through the modules).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "lancer/math/vec3.hpp"

namespace lancer {

// One pixel: linear RGB (any value; encoding clamps to [0, 1]) and coverage alpha.
struct Rgba {
  float r = 0, g = 0, b = 0, a = 1;

  constexpr Vec3 rgb() const { return {r, g, b}; }
  friend constexpr bool operator==(const Rgba&, const Rgba&) = default;
};

constexpr Rgba toRgba(const Vec3& colour, float alpha = 1) { return {colour.x, colour.y, colour.z, alpha}; }

// Porter-Duff "over" of `colour` with opacity `alpha` onto a pixel with straight (not premultiplied)
// alpha: text, lines and legend panels drawn onto a picture, opaque or transparent.
inline void blendOver(Rgba& pixel, const Vec3& colour, float alpha) {
  if (!(alpha > 0)) return;
  const float below = pixel.a * (1 - alpha);
  const float total = alpha + below;
  pixel.r = (colour.x * alpha + pixel.r * below) / total;
  pixel.g = (colour.y * alpha + pixel.g * below) / total;
  pixel.b = (colour.z * alpha + pixel.b * below) / total;
  pixel.a = total;
}

// The largest width or height of an Image and of what the image writers accept: GIF's 16-bit limit.
// Users get less: scenes and the CLI's --width and --height allow up to kMaxRenderSide (32768,
// scene/render_limits.hpp), so this bound only catches a library caller's bug.
inline constexpr int kMaxImageSide = 65535;

// Threads may write distinct pixels (e.g. disjoint tiles through pasteTile or at()) concurrently:
// pixels are plain elements of one vector and no call but the constructor allocates.
class Image {
 public:
  Image() = default;
  // Throws std::invalid_argument for a negative size or one above kMaxImageSide (a caller's bug).
  Image(int width, int height, Rgba fill = {});

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return pixels_.empty(); }

  Rgba& at(int x, int y) { return pixels_[index(x, y)]; }
  const Rgba& at(int x, int y) const { return pixels_[index(x, y)]; }
  void setRgb(int x, int y, const Vec3& colour, float alpha = 1) { at(x, y) = toRgba(colour, alpha); }

  std::span<Rgba> row(int y) { return {pixels_.data() + index(0, y), static_cast<std::size_t>(width_)}; }
  std::span<const Rgba> row(int y) const {
    return {pixels_.data() + index(0, y), static_cast<std::size_t>(width_)};
  }
  std::span<Rgba> pixels() { return pixels_; }
  std::span<const Rgba> pixels() const { return pixels_; }

  void fill(const Rgba& value);
  // Copies `tile` into this image with its top-left corner at (x0, y0); it must lie inside
  // (std::invalid_argument otherwise). Disjoint tiles may be pasted from several threads at once.
  void pasteTile(const Image& tile, int x0, int y0);
  // The width x height block at (x0, y0); it must lie inside.
  Image crop(int x0, int y0, int width, int height) const;

  // True when some pixel's alpha encodes below 255, i.e. an 8-bit file needs an alpha channel.
  bool hasTransparency() const;

  friend bool operator==(const Image&, const Image&) = default;

 private:
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
  }

  int width_ = 0;
  int height_ = 0;
  std::vector<Rgba> pixels_;
};

}  // namespace lancer
