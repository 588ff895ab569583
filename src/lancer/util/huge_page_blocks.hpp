// Large blocks on transparent huge pages, for the CLI's operator new (apps/lancer/large_allocations.cpp).
// A fresh 4 KiB page costs a page fault of 12-15 us on a virtual machine, and a render of a
// million-face mesh touched about 40,000 of them, a quarter of its CPU time (bench/RESULTS.md, "Page
// faults"). A block of kLargeBlockBytes or more is mapped on its own (as glibc does above
// M_MMAP_THRESHOLD), aligned to 2 MiB and advised MADV_HUGEPAGE before its first touch, so that
// filling it faults once per 2 MiB; freeing it unmaps it, so the memory goes back to the system.
#pragma once

#include <cstddef>

namespace lancer {

inline constexpr std::size_t kLargeBlockBytes = std::size_t{1} << 20;
// The alignment of a large block's first byte (every alignment operator new is asked for up to it).
inline constexpr std::size_t kLargeBlockAlignment = 64;

// A block of at least `bytes` (kLargeBlockBytes or more meant), aligned to kLargeBlockAlignment;
// nullptr when the system has no memory for it.
void* allocateLargeBlock(std::size_t bytes) noexcept;

// Whether `pointer` is a block allocateLargeBlock handed out and not yet released. Any pointer that
// malloc, aligned_alloc or allocateLargeBlock returned may be asked about.
bool isLargeBlock(const void* pointer) noexcept;

// Unmaps a block allocateLargeBlock handed out.
void releaseLargeBlock(void* pointer) noexcept;

// The bytes mapped for a block (its size rounded up to whole 2 MiB pages, with its header).
std::size_t largeBlockMappedBytes(const void* pointer) noexcept;

}  // namespace lancer
