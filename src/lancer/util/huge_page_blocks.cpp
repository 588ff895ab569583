#include "lancer/util/huge_page_blocks.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <mutex>
#include <new>

namespace lancer {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
// The block's header sits at the start of its 2 MiB-aligned mapping, in front of the bytes handed
// out: the pointer handed out is always kHeaderBytes past a 2 MiB boundary, which, with the magic
// word, tells a large block from malloc's (an unsized operator delete gets either).
constexpr std::size_t kHeaderBytes = kLargeBlockAlignment;
constexpr std::uint64_t kMagic = 0x6c616e6365726870ull;  // "lancerhp"

struct Header {
  std::uint64_t magic;  // kMagic ^ the header's address while handed out, 0 while kept or gone
  std::size_t mappedBytes;
};
static_assert(sizeof(Header) <= kHeaderBytes);

std::size_t roundUp(std::size_t bytes, std::size_t to) { return (bytes + to - 1) / to * to; }

// The header of a block allocateLargeBlock handed out, or nullptr. A pointer kHeaderBytes past a
// 2 MiB boundary lies in the same 4 KiB page as that boundary, so the read is safe for any pointer
// an allocator returned.
Header* headerOf(const void* pointer) {
  const auto address = reinterpret_cast<std::uintptr_t>(pointer);
  if ((address & (kHugePage - 1)) != kHeaderBytes) return nullptr;
  auto* header = reinterpret_cast<Header*>(address - kHeaderBytes);
  return header->magic == (kMagic ^ (address - kHeaderBytes)) ? header : nullptr;
}

// Moves the pages of [from, from + bytes) to [to, to + bytes), over what was mapped there, without
// copying or clearing them (the page tables move; a 2 MiB page moves as one entry). Both ends
// 2 MiB-aligned. The range may span several mappings (a kept block's advised pages and its last
// one), which mremap moves one at a time on kernels before 6.17: then the 2 MiB pieces go one by
// one, each within one mapping. A piece that cannot move is unmapped and its place mapped fresh;
// false when even that fails (the system is out of mappings or memory): the destination has a hole.
bool movePages(char* from, char* to, std::size_t bytes) {
  if (::mremap(from, bytes, bytes, MREMAP_MAYMOVE | MREMAP_FIXED, to) != MAP_FAILED) return true;
  bool whole = true;
  for (std::size_t offset = 0; offset < bytes; offset += kHugePage) {
    if (::mremap(from + offset, kHugePage, kHugePage, MREMAP_MAYMOVE | MREMAP_FIXED, to + offset) !=
        MAP_FAILED)
      continue;
    // A failed move may already have unmapped its destination: map it again, blank.
    ::munmap(from + offset, kHugePage);
    if (::mmap(to + offset, kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1,
               0) == MAP_FAILED)
      whole = false;
  }
  return whole;
}

// The whole huge pages of a block of `mapped` bytes that hold `used` bytes, and its last one when at
// least half of it is used (fewer faults than 4 KiB pages); a last page holding a few bytes (a vector
// of exactly 4 MiB, and the header) would take 2 MiB of memory for them, 4 KiB pages only the bytes
// touched.
std::size_t advisedBytes(std::size_t mapped, std::size_t used) {
  std::size_t advised = used / kHugePage * kHugePage;
  if (used - advised >= kHugePage / 2) advised = mapped;
  return advised;
}

// A fresh mapping of `mapped` bytes (whole huge pages), 2 MiB-aligned and advised where `used` bytes
// fill its pages, none of them touched yet; nullptr when the system has no memory for it.
char* mapBlock(std::size_t mapped, std::size_t used) {
  // One huge page more than needed, so that a 2 MiB boundary lies in it; the ends are given back.
  const std::size_t reserved = mapped + kHugePage;
  void* raw = ::mmap(nullptr, reserved, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) return nullptr;
  const auto begin = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (begin + kHugePage - 1) & ~(kHugePage - 1);
  if (aligned > begin) ::munmap(raw, aligned - begin);
  const std::uintptr_t end = begin + reserved;
  if (end > aligned + mapped) ::munmap(reinterpret_cast<void*>(aligned + mapped), end - (aligned + mapped));
  // Advice only: where THP is off, the pages stay 4 KiB and nothing else changes.
  const std::size_t advised = advisedBytes(mapped, used);
  if (advised > 0) ::madvise(reinterpret_cast<void*>(aligned), advised, MADV_HUGEPAGE);
  return reinterpret_cast<char*>(aligned);
}

// The kept blocks and the accounting, under one lock (large blocks are few: a render asks for some
// tens). A fixed table, so that the allocator allocates nothing itself.
class Arena {
 public:
  Header* take(std::size_t mapped, std::size_t used) {
    const std::lock_guard lock(mutex_);
    // The smallest kept block that fits, cut to the request (its end goes back to the system): so
    // the bytes in use are what they would be with nothing kept.
    std::size_t best = count_;
    for (std::size_t i = 0; i < count_; ++i) {
      const std::size_t size = kept_[i]->mappedBytes;
      if (size >= mapped && (best == count_ || size < kept_[best]->mappedBytes)) best = i;
    }
    if (best < count_) {
      Header* header = kept_[best];
      removeKept(best);
      stats_.retainedBytes -= header->mappedBytes;
      if (header->mappedBytes > mapped) {
        ::munmap(reinterpret_cast<char*>(header) + mapped, header->mappedBytes - mapped);
        header->mappedBytes = mapped;
      }
      stats_.inUseBytes += header->mappedBytes;
      ++stats_.reusedBlocks;
      return header;
    }
    // None fits (every kept block is smaller): the block is made of kept ones, their pages moved
    // side by side (the largest first; the last cut to what is left), and fresh pages only past
    // them. A fresh page costs the kernel a clear of its bytes on first touch (a sixth of a 1M
    // render's CPU time went to it); a moved one costs nothing and holds what its last user wrote.
    // Every kept byte is taken before any is mapped fresh, so in use + kept grows past what it was
    // only to what is in use.
    char* block = mapBlock(mapped, used);
    if (block == nullptr) return nullptr;
    std::size_t filled = 0;
    while (filled < mapped && count_ > 0) {
      const std::size_t largest = static_cast<std::size_t>(
          std::max_element(kept_.begin(), kept_.begin() + count_,
                           [](const Header* a, const Header* b) { return a->mappedBytes < b->mappedBytes; }) -
          kept_.begin());
      Header* kept = kept_[largest];
      const std::size_t size = kept->mappedBytes;
      const std::size_t moved = std::min(size, mapped - filled);
      removeKept(largest);
      stats_.retainedBytes -= size;
      auto* from = reinterpret_cast<char*>(kept);
      if (moved < size) ::munmap(from + moved, size - moved);
      const bool whole = movePages(from, block + filled, moved);
      filled += moved;
      ++stats_.movedBlocks;
      if (!whole) {  // a hole in the block: give it all back, as a failed fresh mapping does
        ::munmap(block, mapped);
        return nullptr;
      }
    }
    // The moved pages take the advice of the block they now belong to.
    if (filled > 0) {
      const std::size_t advised = advisedBytes(mapped, used);
      if (advised > 0) ::madvise(block, advised, MADV_HUGEPAGE);
    }
    if (filled < mapped) ++stats_.mappedBlocks;
    auto* header = reinterpret_cast<Header*>(block);  // written once the pages are in place
    header->mappedBytes = mapped;
    stats_.inUseBytes += mapped;
    stats_.peakMappedBytes = std::max(stats_.peakMappedBytes, stats_.inUseBytes + stats_.retainedBytes);
    return header;
  }

  void give(Header* header) {
    const std::lock_guard lock(mutex_);
    stats_.inUseBytes -= header->mappedBytes;
    if (count_ == kept_.size()) unmapKept(0);  // the oldest makes room
    kept_[count_++] = header;
    stats_.retainedBytes += header->mappedBytes;
  }

  void releaseAll() {
    const std::lock_guard lock(mutex_);
    while (count_ > 0) unmapKept(count_ - 1);
  }

  LargeBlockStats stats() {
    const std::lock_guard lock(mutex_);
    return stats_;
  }

 private:
  void removeKept(std::size_t i) {
    std::copy(kept_.begin() + i + 1, kept_.begin() + count_, kept_.begin() + i);
    --count_;
  }

  std::size_t unmapKept(std::size_t i) {
    Header* header = kept_[i];
    const std::size_t mapped = header->mappedBytes;
    removeKept(i);
    stats_.retainedBytes -= mapped;
    ++stats_.unmappedBlocks;
    ::munmap(header, mapped);
    return mapped;
  }

  std::mutex mutex_;
  std::array<Header*, 64> kept_{};
  std::size_t count_ = 0;
  LargeBlockStats stats_;
};

// Never destroyed: operator delete may run after static destructors (the kept blocks go with the
// process). In storage of its own: operator new is what calls it.
Arena& arena() {
  alignas(Arena) static unsigned char storage[sizeof(Arena)];
  static Arena* const instance = new (storage) Arena;
  return *instance;
}

}  // namespace

void* allocateLargeBlock(std::size_t bytes) noexcept {
  if (bytes > SIZE_MAX / 2 - 2 * kHugePage) return nullptr;
  Header* header = arena().take(roundUp(bytes + kHeaderBytes, kHugePage), bytes + kHeaderBytes);
  if (header == nullptr) return nullptr;
  header->magic = kMagic ^ reinterpret_cast<std::uintptr_t>(header);
  return reinterpret_cast<char*>(header) + kHeaderBytes;
}

bool isLargeBlock(const void* pointer) noexcept { return headerOf(pointer) != nullptr; }

std::size_t largeBlockMappedBytes(const void* pointer) noexcept {
  const Header* header = headerOf(pointer);
  return header ? header->mappedBytes : 0;
}

void releaseLargeBlock(void* pointer) noexcept {
  Header* header = headerOf(pointer);
  if (header == nullptr) return;
  header->magic = 0;
  arena().give(header);
}

void releaseRetainedLargeBlocks() noexcept { arena().releaseAll(); }

LargeBlockStats largeBlockStats() noexcept { return arena().stats(); }

}  // namespace lancer
