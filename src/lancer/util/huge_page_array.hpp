// A large array of plain items, advised for transparent huge pages and left unwritten, for buffers
// that a parallel loop fills: its first touch is that loop, on every thread, not a vector's
// value-initialising resize (which faults every page in on one thread and writes it twice).
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <type_traits>

#include "lancer/util/huge_pages.hpp"

namespace lancer {

template <typename T>
class HugePageArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  HugePageArray() = default;
  // `count` items, not initialised.
  explicit HugePageArray(std::size_t count)
      : items_(count ? std::make_unique_for_overwrite<T[]>(count) : nullptr), size_(count) {
    adviseHugePages(items_.get(), count * sizeof(T));
  }

  T* data() { return items_.get(); }
  const T* data() const { return items_.get(); }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](std::size_t i) { return items_[i]; }
  const T& operator[](std::size_t i) const { return items_[i]; }
  std::span<T> span() { return {data(), size_}; }
  std::span<const T> span() const { return {data(), size_}; }
  // Gives the memory back.
  void reset() {
    items_.reset();
    size_ = 0;
  }

 private:
  std::unique_ptr<T[]> items_;
  std::size_t size_ = 0;
};

}  // namespace lancer
