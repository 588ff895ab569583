#include "lancer/util/huge_page_blocks.hpp"

#include <sys/mman.h>

#include <cstdint>

namespace lancer {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
// The block's header sits at the start of its 2 MiB-aligned mapping, in front of the bytes handed
// out: the pointer handed out is always kHeaderBytes past a 2 MiB boundary, which, with the magic
// word, tells a large block from malloc's (an unsized operator delete gets either).
constexpr std::size_t kHeaderBytes = kLargeBlockAlignment;
constexpr std::uint64_t kMagic = 0x6c616e6365726870ull;  // "lancerhp"

struct Header {
  std::uint64_t magic;  // kMagic ^ the header's address
  std::size_t mappedBytes;
};
static_assert(sizeof(Header) <= kHeaderBytes);

std::size_t roundUp(std::size_t bytes, std::size_t to) { return (bytes + to - 1) / to * to; }

// The header of a block allocateLargeBlock handed out, or nullptr. A pointer kHeaderBytes past a
// 2 MiB boundary lies in the same 4 KiB page as that boundary, so the read is safe for any pointer
// an allocator returned.
const Header* headerOf(const void* pointer) {
  const auto address = reinterpret_cast<std::uintptr_t>(pointer);
  if ((address & (kHugePage - 1)) != kHeaderBytes) return nullptr;
  const auto* header = reinterpret_cast<const Header*>(address - kHeaderBytes);
  return header->magic == (kMagic ^ (address - kHeaderBytes)) ? header : nullptr;
}

}  // namespace

void* allocateLargeBlock(std::size_t bytes) noexcept {
  if (bytes > SIZE_MAX / 2 - 2 * kHugePage) return nullptr;
  const std::size_t mapped = roundUp(bytes + kHeaderBytes, kHugePage);
  // One huge page more than needed, so that a 2 MiB boundary lies in it; the ends are given back.
  const std::size_t reserved = mapped + kHugePage;
  void* raw = ::mmap(nullptr, reserved, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) return nullptr;
  const auto begin = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (begin + kHugePage - 1) & ~(kHugePage - 1);
  if (aligned > begin) ::munmap(raw, aligned - begin);
  const std::uintptr_t end = begin + reserved;
  if (end > aligned + mapped) ::munmap(reinterpret_cast<void*>(aligned + mapped), end - (aligned + mapped));
  // Advice only: where THP is off, the pages stay 4 KiB and nothing else changes. The last huge
  // page too: partly filled, it costs less than up to 511 faults of 4 KiB.
  ::madvise(reinterpret_cast<void*>(aligned), mapped, MADV_HUGEPAGE);
  auto* header = reinterpret_cast<Header*>(aligned);
  header->magic = kMagic ^ aligned;
  header->mappedBytes = mapped;
  return reinterpret_cast<char*>(aligned) + kHeaderBytes;
}

bool isLargeBlock(const void* pointer) noexcept { return headerOf(pointer) != nullptr; }

std::size_t largeBlockMappedBytes(const void* pointer) noexcept {
  const Header* header = headerOf(pointer);
  return header ? header->mappedBytes : 0;
}

void releaseLargeBlock(void* pointer) noexcept {
  const Header* found = headerOf(pointer);
  if (found == nullptr) return;
  auto* header = const_cast<Header*>(found);
  const std::size_t mapped = header->mappedBytes;
  header->magic = 0;
  ::munmap(header, mapped);
}

}  // namespace lancer
