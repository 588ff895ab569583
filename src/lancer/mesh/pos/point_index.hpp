// Numbers the distinct points of a list-based view: a .pos file repeats each node's coordinates in
// every element that uses it, and a point is one node when its coordinates are the same numbers.
// An open-addressing hash table on the exact values (-0 and 0 are one value), grown as points come.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

#include "lancer/math/vec3.hpp"
#include "lancer/util/huge_pages.hpp"

namespace lancer {

template <typename T>
class PointIndex {
 public:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

  // A table for `expected` points, and room for a quarter more (a mesh's boundary adds nodes to a
  // count from its element count): growing copies every point; unused room costs no memory.
  explicit PointIndex(std::size_t expected = 0) {
    rehash(std::bit_ceil(std::max<std::size_t>(expected * 2, 64)));
    points_.reserve(expected + expected / 4);
    adviseHugePages(points_);
  }

  // The number of `p`, given to it now when it is new (then points() grows by one).
  std::uint32_t insert(const Vec3T<T>& p) {
    const Vec3T<T> key = canonical(p);
    const std::size_t h = hash(key);
    // A file lists each node with every element that uses it, and neighbours close together (in
    // mesh order): most points were met a few elements before, and are found in the small table of
    // recent points (in cache) without a miss in the large one.
    Recent& recent = recent_[h & (kRecent - 1)];
    if (recent.id != kNone && recent.point == key) return recent.id;
    std::size_t slot = h & mask_;
    std::uint32_t id;
    for (;; slot = (slot + 1) & mask_) {
      id = slots_[slot];
      if (id == kNone || points_[id] == key) break;
    }
    if (id == kNone) {
      id = static_cast<std::uint32_t>(points_.size());
      points_.push_back(key);
      slots_[slot] = id;
      if (points_.size() * 2 > slots_.size()) rehash(slots_.size() * 2);
    }
    recent = {key, id};
    return id;
  }
  // Asks the cache for where insert(p) will look in the large table: called an element ahead, it
  // hides the miss that a point met for the first time (or long ago) costs.
  void prefetch(const Vec3T<T>& p) const { __builtin_prefetch(&slots_[hash(canonical(p)) & mask_]); }
  // The number of `p`, or kNone when it was never inserted.
  std::uint32_t find(const Vec3T<T>& p) const {
    const Vec3T<T> key = canonical(p);
    for (std::size_t slot = hash(key) & mask_;; slot = (slot + 1) & mask_) {
      const std::uint32_t id = slots_[slot];
      if (id == kNone || points_[id] == key) return id;
    }
  }
  const std::vector<Vec3T<T>>& points() const { return points_; }
  std::vector<Vec3T<T>>& points() { return points_; }
  std::size_t size() const { return points_.size(); }

 private:
  // Adding 0 turns -0 into +0, so that the bits hashed are those of equal values.
  static Vec3T<T> canonical(const Vec3T<T>& p) { return {p.x + T(0), p.y + T(0), p.z + T(0)}; }
  static std::uint64_t bitsOf(T v) {
    if constexpr (sizeof(T) == 8) {
      return std::bit_cast<std::uint64_t>(v);
    } else {
      return std::bit_cast<std::uint32_t>(v);
    }
  }
  // A multiply-xorshift mix of the three values' bits (the low bits of coordinates that differ in
  // their last digits are what sets points apart).
  static std::size_t hash(const Vec3T<T>& p) {
    std::uint64_t h = bitsOf(p.x) * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 29) ^ bitsOf(p.y)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 31) ^ bitsOf(p.z)) * 0x94D049BB133111EBull;
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
  void rehash(std::size_t size) {
    slots_ =
        vectorOnHugePages(size, kNone);  // TLB misses in a table of 4 KiB pages cost as much as cache misses
    mask_ = size - 1;
    for (std::uint32_t id = 0; id < points_.size(); ++id) {
      std::size_t slot = hash(points_[id]) & mask_;
      while (slots_[slot] != kNone) slot = (slot + 1) & mask_;
      slots_[slot] = id;
    }
  }

  struct Recent {
    Vec3T<T> point;
    std::uint32_t id = kNone;
  };
  static constexpr std::size_t kRecent = 16384;  // 512 KiB for doubles: in L2

  std::vector<std::uint32_t> slots_;
  std::size_t mask_ = 0;
  std::vector<Vec3T<T>> points_;
  std::vector<Recent> recent_ = std::vector<Recent>(kRecent);
};

}  // namespace lancer
