// Colour quantisation for GIF: choosing at most 256 colours that represent one or many frames
// (Wu's variance-minimising cuts), and finding the nearest palette colour for any pixel.
#pragma once

#include <cstdint>
#include <span>
#include <unordered_set>
#include <vector>

namespace lancer {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend constexpr bool operator==(const Rgb8&, const Rgb8&) = default;
};

using Palette = std::vector<Rgb8>;

// Accumulates the colours of any number of images (interleaved 8-bit RGB), then builds a palette:
// - when the images hold at most maxColours distinct colours, exactly those colours (sorted), so
//   flat-shaded or synthetic images are reproduced without error;
// - otherwise Xiaolin Wu, "Efficient Statistical Computations for Optimal Color Quantization",
//   Graphics Gems II (1991): a 33^3 histogram of colour moments, boxes cut greedily where the
//   summed squared error drops most. Palette entries are the exact means of their pixels.
// Memory is fixed (about 1.4 MiB) whatever the number of pixels added.
class PaletteBuilder {
 public:
  explicit PaletteBuilder(int maxColours = 256);  // 1..256
  void add(std::span<const std::uint8_t> rgb);
  Palette build() const;
  // True while the colours seen fit the budget: build() then returns them exactly.
  bool exact() const { return fewColours_; }

 private:
  int maxColours_;
  bool fewColours_ = true;  // false once more than maxColours_ distinct colours were seen
  std::unordered_set<std::uint32_t> distinct_;
  // Moments per histogram cell (5 bits per channel, index 0 left empty for the cumulative sums).
  std::vector<std::int64_t> weight_, sumR_, sumG_, sumB_;
  std::vector<double> sumSquares_;
};

// Convenience: the palette of one image.
Palette quantize(std::span<const std::uint8_t> rgb, int maxColours = 256);

// Exact nearest palette colour (squared RGB distance; ties go to the lower index). Entries are
// sorted by green and searched outwards with pruning, and recent answers are cached, so a lookup
// usually costs a few comparisons.
class NearestColour {
 public:
  explicit NearestColour(const Palette& palette);
  std::uint8_t operator()(int r, int g, int b);
  const Palette& palette() const { return palette_; }

 private:
  std::uint8_t search(int r, int g, int b) const;

  Palette palette_;
  std::vector<Rgb8> sorted_;               // palette_ sorted by green
  std::vector<std::uint8_t> sortedIndex_;  // palette index of each sorted_ entry
  std::vector<std::uint32_t> cacheKey_;    // packed colour | 1 << 24; 0 = empty slot
  std::vector<std::uint8_t> cacheValue_;
};

}  // namespace lancer
