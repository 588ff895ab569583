#include "lancer/image/dither.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace lancer {
namespace {

// Bayer's recursive index matrix for 8x8 ordered dithering; values 0..63.
constexpr std::array<std::array<int, 8>, 8> kBayer8 = {{
    {0, 32, 8, 40, 2, 34, 10, 42},
    {48, 16, 56, 24, 50, 18, 58, 26},
    {12, 44, 4, 36, 14, 46, 6, 38},
    {60, 28, 52, 20, 62, 30, 54, 22},
    {3, 35, 11, 43, 1, 33, 9, 41},
    {51, 19, 59, 27, 49, 17, 57, 25},
    {15, 47, 7, 39, 13, 45, 5, 37},
    {63, 31, 55, 23, 61, 29, 53, 21},
}};

int clampByte(float v) { return static_cast<int>(std::clamp(std::lround(v), 0L, 255L)); }

// The typical distance between neighbouring palette colours: the median over entries of the distance
// to the nearest other entry. Ordered dithering spreads its thresholds over this step, divided by
// sqrt(3) since the offset moves all three channels together (black to white: 441 / sqrt(3) = 255).
float paletteStep(const Palette& palette) {
  if (palette.size() < 2) return 0.0f;
  std::vector<float> nearest;
  for (std::size_t i = 0; i < palette.size(); ++i) {
    int best = 1 << 30;
    for (std::size_t j = 0; j < palette.size(); ++j) {
      if (i == j) continue;
      const int dr = palette[i].r - palette[j].r, dg = palette[i].g - palette[j].g,
                db = palette[i].b - palette[j].b;
      best = std::min(best, dr * dr + dg * dg + db * db);
    }
    nearest.push_back(std::sqrt(static_cast<float>(best)));
  }
  std::nth_element(nearest.begin(), nearest.begin() + static_cast<std::ptrdiff_t>(nearest.size() / 2),
                   nearest.end());
  return nearest[nearest.size() / 2];
}

void mapOrdered(std::span<const std::uint8_t> rgb, int width, int height, NearestColour& nearest,
                std::span<std::uint8_t> indices) {
  const float step = paletteStep(nearest.palette()) / std::sqrt(3.0f);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
      const float offset =
          ((static_cast<float>(kBayer8[static_cast<std::size_t>(y & 7)][static_cast<std::size_t>(x & 7)]) +
            0.5f) /
               64.0f -
           0.5f) *
          step;
      indices[i] = nearest(clampByte(rgb[3 * i] + offset), clampByte(rgb[3 * i + 1] + offset),
                           clampByte(rgb[3 * i + 2] + offset));
    }
  }
}

void mapFloydSteinberg(std::span<const std::uint8_t> rgb, int width, int height, NearestColour& nearest,
                       std::span<std::uint8_t> indices) {
  // Error carried into the current and the next row, with one guard pixel on each side.
  const std::size_t rowSize = static_cast<std::size_t>(width + 2) * 3;
  std::vector<float> current(rowSize, 0.0f), next(rowSize, 0.0f);
  const Palette& palette = nearest.palette();
  for (int y = 0; y < height; ++y) {
    const bool leftToRight = (y % 2) == 0;
    const int direction = leftToRight ? 1 : -1;
    for (int k = 0; k < width; ++k) {
      const int x = leftToRight ? k : width - 1 - k;
      const std::size_t i =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
      const std::size_t e = static_cast<std::size_t>(x + 1) * 3;
      std::array<int, 3> wanted{};
      for (std::size_t c = 0; c < 3; ++c) wanted[c] = clampByte(rgb[3 * i + c] + current[e + c]);
      const std::uint8_t index = nearest(wanted[0], wanted[1], wanted[2]);
      indices[i] = index;
      const std::array<int, 3> got = {palette[index].r, palette[index].g, palette[index].b};
      for (std::size_t c = 0; c < 3; ++c) {
        const float error = static_cast<float>(wanted[c] - got[c]);
        const std::size_t ahead = static_cast<std::size_t>(static_cast<int>(e) + 3 * direction) + c;
        const std::size_t behind = static_cast<std::size_t>(static_cast<int>(e) - 3 * direction) + c;
        current[ahead] += error * (7.0f / 16.0f);
        next[behind] += error * (3.0f / 16.0f);
        next[e + c] += error * (5.0f / 16.0f);
        next[ahead] += error * (1.0f / 16.0f);
      }
    }
    std::swap(current, next);
    std::fill(next.begin(), next.end(), 0.0f);
  }
}

}  // namespace

void mapToPalette(std::span<const std::uint8_t> rgb, int width, int height, NearestColour& nearest,
                  Dither dither, std::span<std::uint8_t> indices) {
  switch (dither) {
    case Dither::None:
      for (std::size_t i = 0; i < indices.size(); ++i)
        indices[i] = nearest(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]);
      return;
    case Dither::Ordered:
      mapOrdered(rgb, width, height, nearest, indices);
      return;
    case Dither::FloydSteinberg:
      mapFloydSteinberg(rgb, width, height, nearest, indices);
      return;
  }
}

}  // namespace lancer
