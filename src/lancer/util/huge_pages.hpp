// Asks the kernel to back a large, freshly reserved array with transparent huge pages, so that
// filling it takes one page fault per 2 MiB instead of one per 4 KiB (first-touch faults dominate
// the load time of a million-face mesh otherwise; bench/msh_load_bench.cpp measures it). The mesh
// reader's and scene's big arrays and the kd build's buffers and layout use it.
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lancer {

// The 2 MiB pages wholly inside [data, data + bytes).
inline void adviseHugePages(const void* data, std::size_t bytes) {
  constexpr std::uintptr_t kHugePage = 2u << 20;
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t end = begin + bytes;
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = end & ~(kHugePage - 1);
  // Advice only: where the kernel has no huge pages (or THP is off) nothing changes.
  if (last > first) ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

template <typename T>
void adviseHugePages(const std::vector<T>& array) {
  adviseHugePages(array.data(), array.capacity() * sizeof(T));
}

// `count` copies of `value` in an array advised as above before its first touch (a vector made
// with its size faults its pages in 4 KiB at a time while it fills them).
template <typename T>
std::vector<T> vectorOnHugePages(std::size_t count, const T& value = T{}) {
  std::vector<T> array;
  array.reserve(count);
  adviseHugePages(array);
  array.resize(count, value);
  return array;
}

}  // namespace lancer
