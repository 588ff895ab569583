// Union-find that also keeps, per element, one bit relative to its set's root: "faces a and b must
// be turned the same way / opposite ways" constraints become unions, and a constraint that
// contradicts the ones before it marks the set broken. Orienting a shell this way walks its edges in
// the order they are stored (one pass, no adjacency lists, no breadth-first queue jumping around
// the face array), and gives for each face whether it must be reversed to agree with its root.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace lancer {

// One 32-bit word per element (elements below 2^31): its parent, and in the top bit its bit relative
// to the parent, or for a root, whether its set is broken. One word, so a step of a find is one
// memory access where separate parent, bit and broken arrays took three (the walk over a big
// mesh's edges misses the cache at nearly every step).
class ParityDisjointSets {
 public:
  static constexpr std::size_t kMaxCount = std::size_t(1) << 31;

  explicit ParityDisjointSets(std::size_t count) : link_(count) { std::iota(link_.begin(), link_.end(), 0u); }

  // The root of x's set and x's bit relative to it; every element on the way is pointed straight at
  // the root (its bit rewritten relative to the root).
  std::pair<std::uint32_t, std::uint8_t> find(std::uint32_t x) {
    std::uint32_t root = x;
    std::uint32_t bit = 0;
    for (std::uint32_t up; (up = link_[root] & kIndex) != root; root = up) bit ^= link_[root] >> 31;
    for (std::uint32_t bitOfX = bit;;) {
      const std::uint32_t next = link_[x] & kIndex;
      if (next == root || next == x) break;
      const std::uint32_t bitOfNext = bitOfX ^ (link_[x] >> 31);
      link_[x] = root | bitOfX << 31;
      x = next;
      bitOfX = bitOfNext;
    }
    return {root, static_cast<std::uint8_t>(bit)};
  }

  // Joins the sets of a and b with the constraint bit(a) ^ bit(b) == differ; a set where the
  // constraints cannot all hold is broken (the smaller index is the root, as in DisjointSets).
  void unite(std::uint32_t a, std::uint32_t b, std::uint8_t differ) {
    const auto [rootA, bitA] = find(a);
    const auto [rootB, bitB] = find(b);
    if (rootA == rootB) {
      if ((bitA ^ bitB) != differ) link_[rootA] |= kBrokenBit;
      return;
    }
    join(rootA, rootB, static_cast<std::uint32_t>(bitA ^ bitB ^ differ));
  }

  // Joins the sets without a constraint between a and b (their bits keep no meaning across it).
  void uniteFree(std::uint32_t a, std::uint32_t b) {
    const std::uint32_t rootA = find(a).first, rootB = find(b).first;
    if (rootA != rootB) join(rootA, rootB, 0);
  }

  bool broken(std::uint32_t root) const { return (link_[root] & kBrokenBit) != 0; }

 private:
  static constexpr std::uint32_t kBrokenBit = 1u << 31;  // the top bit, read at a root
  static constexpr std::uint32_t kIndex = kBrokenBit - 1;

  void join(std::uint32_t rootA, std::uint32_t rootB, std::uint32_t bitOfChild) {
    const std::uint32_t root = std::min(rootA, rootB), child = std::max(rootA, rootB);
    link_[root] |= link_[child] & kBrokenBit;
    link_[child] = root | bitOfChild << 31;
  }

  std::vector<std::uint32_t> link_;
};

}  // namespace lancer
