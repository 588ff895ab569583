// The memory arena of the CLI and the Python module: their C++ allocations of a megabyte and more (a
// mesh's arrays, the scene's, the accelerator's build buffers and tree), handed out by the
// replacement of the global operator new (apps/lancer/large_allocations.cpp).
//
// A fresh 4 KiB page costs a page fault of 12-15 us on a virtual machine, and a render of a
// million-face mesh touched about 40,000 of them, a quarter of its CPU time (bench/RESULTS.md, "Page
// faults"). A block of kLargeBlockBytes or more is mapped on its own (as glibc does above
// M_MMAP_THRESHOLD), aligned to 2 MiB and advised MADV_HUGEPAGE before its first touch, so that
// filling it faults once per 2 MiB.
//
// A released block is kept, its pages still faulted in, for the next request it fits (the frames of
// an animation, the renders of a Python session ask for the same sizes again): taken again, it costs
// no fault at all (a larger block is cut to the request: its end goes back to the system). A request
// that no kept block fits is made of kept blocks, their pages moved side by side (mremap: no copy,
// no clear), and fresh pages only for the rest, so that the stages of a render reuse what the ones
// before them gave back (the mesh as read, the orientation's and the normals' working arrays). What
// is kept does not raise the peak: every kept byte is taken before any is mapped fresh, so that in
// use + kept grows past what it was only to what is in use.
// releaseRetainedLargeBlocks gives them all back.
#pragma once

#include <cstddef>
#include <cstdint>

namespace lancer {

inline constexpr std::size_t kLargeBlockBytes = std::size_t{1} << 20;
// The alignment of a large block's first byte (every alignment operator new is asked for up to it).
inline constexpr std::size_t kLargeBlockAlignment = 64;

// A block of at least `bytes` (kLargeBlockBytes or more meant), aligned to kLargeBlockAlignment;
// nullptr when the system has no memory for it. Its bytes are not cleared (a kept block holds what
// its last user wrote).
void* allocateLargeBlock(std::size_t bytes) noexcept;

// Whether `pointer` is a block allocateLargeBlock handed out and not yet released. Any pointer that
// malloc, aligned_alloc or allocateLargeBlock returned may be asked about.
bool isLargeBlock(const void* pointer) noexcept;

// Gives back a block allocateLargeBlock handed out: kept for reuse, or unmapped.
void releaseLargeBlock(void* pointer) noexcept;

// The bytes mapped for a block (its size rounded up to whole 2 MiB pages, with its header).
std::size_t largeBlockMappedBytes(const void* pointer) noexcept;

// Unmaps every kept block (the memory goes back to the system).
void releaseRetainedLargeBlocks() noexcept;

// The arena's accounting, in bytes mapped (whole 2 MiB pages, headers included) and blocks.
struct LargeBlockStats {
  std::size_t inUseBytes = 0;        // handed out and not released
  std::size_t retainedBytes = 0;     // released and kept for reuse
  std::size_t peakMappedBytes = 0;   // the most of in use + retained at any time
  std::uint64_t mappedBlocks = 0;    // blocks mapped fresh
  std::uint64_t reusedBlocks = 0;    // requests served by a kept block
  std::uint64_t unmappedBlocks = 0;  // blocks given back to the system
  std::uint64_t movedBlocks = 0;     // kept blocks moved into a larger request
};
LargeBlockStats largeBlockStats() noexcept;

}  // namespace lancer
