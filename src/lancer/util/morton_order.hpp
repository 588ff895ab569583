// Morton (Z-order) codes of points in a box and a stable parallel sort by them: the order the BVH
// build gives its face references (accel/bvh/morton.hpp) and the one meshes are renumbered in
// (mesh/morton_renumbering.hpp), so that what lies near in space lies near in memory.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lancer {

inline constexpr int kMortonBitsPerAxis = 10;  // 30-bit codes

// x's low 10 bits spread to every third bit.
inline std::uint32_t spreadMortonBits(std::uint32_t x) {
  x &= 0x3FFu;
  x = (x | (x << 16)) & 0x030000FFu;
  x = (x | (x << 8)) & 0x0300F00Fu;
  x = (x | (x << 4)) & 0x030C30C3u;
  x = (x | (x << 2)) & 0x09249249u;
  return x;
}

// The 30-bit codes of points of the box [lo, hi]: 2^10 cells an axis, a flat axis all in cell 0,
// points outside (and NaN) in the nearest cell.
class MortonGrid {
 public:
  MortonGrid(const float lo[3], const float hi[3]) {
    for (int a = 0; a < 3; ++a) {
      const float extent = hi[a] - lo[a];
      origin_[a] = lo[a];
      scale_[a] = extent > 0.0f && std::isfinite(extent) ? kCells * (1.0f - 1e-5f) / extent : 0.0f;
    }
  }
  std::uint32_t code(const float p[3]) const {
    std::uint32_t code = 0;
    for (int a = 0; a < 3; ++a) {
      float cell = (p[a] - origin_[a]) * scale_[a];
      cell = cell > 0.0f ? std::min(cell, kCells - 1.0f) : 0.0f;  // NaN to 0 too
      code |= spreadMortonBits(static_cast<std::uint32_t>(cell)) << a;
    }
    return code;
  }

 private:
  static constexpr float kCells = float(1u << kMortonBitsPerAxis);
  float origin_[3];
  float scale_[3];
};

// Keys code << 32 | index sorted by their 30-bit code, equal codes in their order before (so the
// order depends on the items alone, not on the thread count): a radix sort on `threads` threads.
void sortMortonKeys(std::vector<std::uint64_t>& keys, int threads);

// The same sort of `count` keys with `scratch` (as many, not initialised) for the passes; returns
// the array the sorted keys end in (`keys` or `scratch`; the other then holds nothing of use).
std::uint64_t* sortMortonKeys(std::uint64_t* keys, std::uint64_t* scratch, std::size_t count, int threads);

}  // namespace lancer
