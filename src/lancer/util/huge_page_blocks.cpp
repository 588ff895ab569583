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

// A fresh mapping of `mapped` bytes (whole huge pages), 2 MiB-aligned and advised where `used` bytes
// fill its pages; nullptr when the system has no memory for it.
Header* mapBlock(std::size_t mapped, std::size_t used) {
  // One huge page more than needed, so that a 2 MiB boundary lies in it; the ends are given back.
  const std::size_t reserved = mapped + kHugePage;
  void* raw = ::mmap(nullptr, reserved, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) return nullptr;
  const auto begin = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (begin + kHugePage - 1) & ~(kHugePage - 1);
  if (aligned > begin) ::munmap(raw, aligned - begin);
  const std::uintptr_t end = begin + reserved;
  if (end > aligned + mapped) ::munmap(reinterpret_cast<void*>(aligned + mapped), end - (aligned + mapped));
  // Advice only: where THP is off, the pages stay 4 KiB and nothing else changes. The whole huge
  // pages the block fills, and its last one when at least half of it is used (fewer faults than
  // 4 KiB pages); a last page holding a few bytes (a vector of exactly 4 MiB, and the header) would
  // take 2 MiB of memory for them, 4 KiB pages only the bytes touched.
  std::size_t advised = used / kHugePage * kHugePage;
  if (used - advised >= kHugePage / 2) advised = mapped;
  if (advised > 0) ::madvise(reinterpret_cast<void*>(aligned), advised, MADV_HUGEPAGE);
  auto* header = reinterpret_cast<Header*>(aligned);
  header->mappedBytes = mapped;
  return header;
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
    // None fits (every kept block is smaller): as many kept bytes unmapped as are mapped fresh (the
    // largest first), so that in use + kept grows past what it was only to what is in use.
    std::size_t freed = 0;
    while (freed < mapped && count_ > 0) {
      const std::size_t largest = static_cast<std::size_t>(
          std::max_element(kept_.begin(), kept_.begin() + count_,
                           [](const Header* a, const Header* b) { return a->mappedBytes < b->mappedBytes; }) -
          kept_.begin());
      freed += unmapKept(largest);
    }
    Header* header = mapBlock(mapped, used);
    if (header == nullptr) return nullptr;
    ++stats_.mappedBlocks;
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
