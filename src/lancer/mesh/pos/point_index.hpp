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
#include "lancer/util/prefetch.hpp"

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
    const std::uint64_t h = hash(key);
    // A file lists each node with every element that uses it, and neighbours close together (in
    // mesh order): most points were met a few elements before, and are found in the small table of
    // recent points (in cache) without a miss in the large one.
    Recent& recent = recent_[h & (kRecent - 1)];
    if (recent.id != kNone && recent.point == key) return recent.id;
    const std::uint64_t tag = h & kTagMask;
    std::size_t slot = h & mask_;
    std::uint32_t id = kNone;
    for (;; slot = (slot + 1) & mask_) {
      const std::uint64_t entry = slots_[slot];
      if (entry == kEmpty) break;
      // The slot keeps the hash's high bits beside the number: a point is read (a miss in the large
      // array of points) only when they match, not for every other point its probe passes.
      if ((entry & kTagMask) == tag && points_[static_cast<std::uint32_t>(entry)] == key) {
        id = static_cast<std::uint32_t>(entry);
        break;
      }
    }
    if (id == kNone) {
      id = static_cast<std::uint32_t>(points_.size());
      points_.push_back(key);
      slots_[slot] = tag | id;
      if (points_.size() * 2 > slots_.size()) rehash(slots_.size() * 2);
    }
    recent = {key, id};
    return id;
  }
  // Asks the cache for where insert(p) will look in the large table, unless the small table of
  // recent points answers it: called a few elements ahead, it hides the miss that a point met for the
  // first time (or long ago) costs. Only those are prefetched, so that the few outstanding misses
  // the core can track are not spent on points that are in cache.
  void prefetch(const Vec3T<T>& p) const {
    const Vec3T<T> key = canonical(p);
    const std::uint64_t h = hash(key);
    const Recent& recent = recent_[h & (kRecent - 1)];
    if (recent.id != kNone && recent.point == key) return;
    prefetchLine(&slots_[h & mask_]);
  }
  // The number of `p`, or kNone when it was never inserted.
  std::uint32_t find(const Vec3T<T>& p) const {
    const Vec3T<T> key = canonical(p);
    const std::uint64_t h = hash(key);
    const std::uint64_t tag = h & kTagMask;
    for (std::size_t slot = h & mask_;; slot = (slot + 1) & mask_) {
      const std::uint64_t entry = slots_[slot];
      if (entry == kEmpty) return kNone;
      if ((entry & kTagMask) == tag && points_[static_cast<std::uint32_t>(entry)] == key)
        return static_cast<std::uint32_t>(entry);
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
  static std::uint64_t hash(const Vec3T<T>& p) {
    std::uint64_t h = bitsOf(p.x) * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 29) ^ bitsOf(p.y)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 31) ^ bitsOf(p.z)) * 0x94D049BB133111EBull;
    return h ^ (h >> 32);
  }
  void rehash(std::size_t size) {
    slots_ =
        vectorOnHugePages(size, kEmpty);  // TLB misses in a table of 4 KiB pages cost as much as cache misses
    mask_ = size - 1;
    for (std::uint32_t id = 0; id < points_.size(); ++id) {
      const std::uint64_t h = hash(points_[id]);
      std::size_t slot = h & mask_;
      while (slots_[slot] != kEmpty) slot = (slot + 1) & mask_;
      slots_[slot] = (h & kTagMask) | id;
    }
  }

  struct Recent {
    Vec3T<T> point;
    std::uint32_t id = kNone;
  };
  static constexpr std::size_t kRecent = 16384;  // 512 KiB for doubles: in L2

  // A slot: the hash's high 32 bits, then the point's number; all ones when empty (no number is
  // kNone, so no entry is).
  static constexpr std::uint64_t kTagMask = 0xFFFFFFFF00000000ull;
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  std::vector<std::uint64_t> slots_;
  std::size_t mask_ = 0;
  std::vector<Vec3T<T>> points_;
  std::vector<Recent> recent_ = std::vector<Recent>(kRecent);
};

}  // namespace lancer
