// The BVH's node: the boxes of up to eight children as eight lanes of each coordinate (one AVX2 load
// per plane, Embree's BVH8 layout) and what each child is: another node or a leaf's triangle run.
#pragma once

#include <cstdint>
#include <limits>

namespace lancer {

struct alignas(32) BvhNode {
  static constexpr int kWidth = 8;
  // lower[axis][child], upper[axis][child]; an empty slot holds an inverted box at infinity, which
  // no ray meets, so the traversal needs no count.
  float lower[3][kWidth];
  float upper[3][kWidth];
  // Child: the index of a node, or kLeaf | (count - 1) << kCountShift | first triangle.
  std::uint32_t child[kWidth];

  static constexpr std::uint32_t kLeaf = 0x80000000u;
  static constexpr int kCountShift = 28;
  static constexpr std::uint32_t kMaxLeafTriangles = 8;
  static constexpr std::uint32_t kMaxFirst = (1u << kCountShift) - 1;
  static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
  // Deepest node (the build keeps to it), so a walk's stack of kMaxDepth * 7 + 1 always suffices.
  static constexpr int kMaxDepth = 80;

  static std::uint32_t leaf(std::uint32_t first, std::uint32_t count) {
    return kLeaf | (count - 1) << kCountShift | first;
  }
  static bool isLeaf(std::uint32_t c) { return (c & kLeaf) != 0; }
  static std::uint32_t leafFirst(std::uint32_t c) { return c & kMaxFirst; }
  static std::uint32_t leafCount(std::uint32_t c) { return ((c >> kCountShift) & 7u) + 1; }

  void clear() {
    for (int k = 0; k < kWidth; ++k) {
      for (int a = 0; a < 3; ++a) {
        lower[a][k] = std::numeric_limits<float>::infinity();
        upper[a][k] = -std::numeric_limits<float>::infinity();
      }
      child[k] = kEmpty;
    }
  }
};
static_assert(sizeof(BvhNode) == 224);

}  // namespace lancer
