// The kd-tree's memory layout: 8-byte nodes (pbrt-v3 section 4.4 / Wald's thesis, section 7.1)
// with sibling pairs adjacent, so one 16-byte fetch brings both children of an inner node.
#pragma once

#include <bit>
#include <cstdint>

namespace lancer {

struct KdNode {
  // Inner node: the split position (float bits). Leaf: the triangle itself when the leaf holds one,
  // else the offset of its first entry in the tree's leaf index array.
  std::uint32_t payload = 0;
  // Low 2 bits: split axis 0..2, or kLeafTag. High 30 bits: index of the first of the two children
  // (left, then right at +1) for an inner node, the triangle count for a leaf.
  std::uint32_t bits = kLeafTag;

  static constexpr std::uint32_t kLeafTag = 3;
  static constexpr std::uint32_t kMaxIndex = (1u << 30) - 1;

  static KdNode inner(int axis, float split, std::uint32_t firstChild) {
    return {std::bit_cast<std::uint32_t>(split), (firstChild << 2) | static_cast<std::uint32_t>(axis)};
  }
  static KdNode leaf(std::uint32_t payload, std::uint32_t count) {
    return {payload, (count << 2) | kLeafTag};
  }

  bool isLeaf() const { return (bits & 3u) == kLeafTag; }
  int axis() const { return static_cast<int>(bits & 3u); }
  float split() const { return std::bit_cast<float>(payload); }
  std::uint32_t firstChild() const { return bits >> 2; }
  std::uint32_t triangleCount() const { return bits >> 2; }
};
static_assert(sizeof(KdNode) == 8, "the traversal's cache behaviour relies on 8-byte nodes");

}  // namespace lancer
