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

class ParityDisjointSets {
 public:
  explicit ParityDisjointSets(std::size_t count) : parent_(count), parity_(count, 0), broken_(count, 0) {
    std::iota(parent_.begin(), parent_.end(), 0u);
  }

  // The root of x's set and x's bit relative to it; every element on the way is pointed straight at
  // the root (its bit rewritten relative to the root).
  std::pair<std::uint32_t, std::uint8_t> find(std::uint32_t x) {
    std::uint32_t root = x;
    std::uint8_t bit = 0;
    while (parent_[root] != root) {
      bit ^= parity_[root];
      root = parent_[root];
    }
    for (std::uint8_t bitOfX = bit; parent_[x] != root && parent_[x] != x;) {
      const std::uint32_t next = parent_[x];
      const std::uint8_t bitOfNext = bitOfX ^ parity_[x];
      parent_[x] = root;
      parity_[x] = bitOfX;
      x = next;
      bitOfX = bitOfNext;
    }
    return {root, bit};
  }

  // Joins the sets of a and b with the constraint bit(a) ^ bit(b) == differ; a set where the
  // constraints cannot all hold is broken (the smaller index is the root, as in DisjointSets).
  void unite(std::uint32_t a, std::uint32_t b, std::uint8_t differ) {
    const auto [rootA, bitA] = find(a);
    const auto [rootB, bitB] = find(b);
    if (rootA == rootB) {
      if ((bitA ^ bitB) != differ) broken_[rootA] = 1;
      return;
    }
    const std::uint32_t root = std::min(rootA, rootB), child = std::max(rootA, rootB);
    parent_[child] = root;
    parity_[child] = bitA ^ bitB ^ differ;
    broken_[root] |= broken_[child];
  }

  // Joins the sets without a constraint between a and b (their bits keep no meaning across it).
  void uniteFree(std::uint32_t a, std::uint32_t b) {
    const std::uint32_t rootA = find(a).first, rootB = find(b).first;
    if (rootA == rootB) return;
    const std::uint32_t root = std::min(rootA, rootB), child = std::max(rootA, rootB);
    parent_[child] = root;
    parity_[child] = 0;
    broken_[root] |= broken_[child];
  }

  bool broken(std::uint32_t root) const { return broken_[root] != 0; }

 private:
  std::vector<std::uint32_t> parent_;
  std::vector<std::uint8_t> parity_;
  std::vector<std::uint8_t> broken_;
};

}  // namespace lancer
