// The C++ allocations of a megabyte and more (a mesh's arrays, the scene's, the accelerator's build
// buffers and tree) in the arena of util/huge_page_blocks.hpp (huge pages, blocks kept for reuse),
// through C++'s own mechanism for it: the replacement of the global operator new and delete. The
// CLI links this file, and so does the Python module, which keeps the replacement to itself (its
// linker script exports nothing else: python/exports.map), so that the interpreter and other
// extensions keep theirs. The library and its tests keep the defaults.
#include <cstddef>
#include <cstdlib>
#include <new>

#include "lancer/util/huge_page_blocks.hpp"

// Sanitizer builds keep the sanitizers' own operator new: their leak checker scans only memory
// it allocated for pointers, so small blocks referenced from the arena's would be reported as
// leaked, and their bounds checks do not see inside the arena's blocks.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define LANCER_KEEP_SANITIZER_ALLOCATOR 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define LANCER_KEEP_SANITIZER_ALLOCATOR 1
#endif
#endif

#ifndef LANCER_KEEP_SANITIZER_ALLOCATOR
namespace {

using lancer::kLargeBlockAlignment;
using lancer::kLargeBlockBytes;

// Calls the new-handler until `attempt` gives memory, as the standard operator new does.
template <typename Attempt>
void* allocateOrThrow(Attempt attempt) {
  for (;;) {
    if (void* pointer = attempt()) return pointer;
    const std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
}

void* allocate(std::size_t bytes) {
  if (bytes >= kLargeBlockBytes) return allocateOrThrow([&] { return lancer::allocateLargeBlock(bytes); });
  return allocateOrThrow([&] { return std::malloc(bytes == 0 ? 1 : bytes); });
}

// Over-aligned types (SIMD nodes): large blocks are aligned to kLargeBlockAlignment; stricter
// alignments, and small blocks, go to aligned_alloc, whose blocks free releases.
void* allocateAligned(std::size_t bytes, std::align_val_t alignment) {
  const auto align = static_cast<std::size_t>(alignment);
  if (bytes >= kLargeBlockBytes && align <= kLargeBlockAlignment) return allocate(bytes);
  const std::size_t rounded = ((bytes == 0 ? 1 : bytes) + align - 1) / align * align;
  return allocateOrThrow([&] { return std::aligned_alloc(align, rounded); });
}

void release(void* pointer) noexcept {
  if (lancer::isLargeBlock(pointer))
    lancer::releaseLargeBlock(pointer);
  else
    std::free(pointer);
}

template <typename Allocate>
void* orNull(Allocate allocation) noexcept {
  try {
    return allocation();
  } catch (...) {
    return nullptr;
  }
}

}  // namespace

void* operator new(std::size_t bytes) { return allocate(bytes); }
void* operator new[](std::size_t bytes) { return allocate(bytes); }
void* operator new(std::size_t bytes, const std::nothrow_t&) noexcept {
  return orNull([&] { return allocate(bytes); });
}
void* operator new[](std::size_t bytes, const std::nothrow_t&) noexcept {
  return orNull([&] { return allocate(bytes); });
}
void* operator new(std::size_t bytes, std::align_val_t alignment) {
  return allocateAligned(bytes, alignment);
}
void* operator new[](std::size_t bytes, std::align_val_t alignment) {
  return allocateAligned(bytes, alignment);
}
void* operator new(std::size_t bytes, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  return orNull([&] { return allocateAligned(bytes, alignment); });
}
void* operator new[](std::size_t bytes, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  return orNull([&] { return allocateAligned(bytes, alignment); });
}

void operator delete(void* pointer) noexcept { release(pointer); }
void operator delete[](void* pointer) noexcept { release(pointer); }
void operator delete(void* pointer, std::size_t) noexcept { release(pointer); }
void operator delete[](void* pointer, std::size_t) noexcept { release(pointer); }
void operator delete(void* pointer, const std::nothrow_t&) noexcept { release(pointer); }
void operator delete[](void* pointer, const std::nothrow_t&) noexcept { release(pointer); }
void operator delete(void* pointer, std::align_val_t) noexcept { release(pointer); }
void operator delete[](void* pointer, std::align_val_t) noexcept { release(pointer); }
void operator delete(void* pointer, std::size_t, std::align_val_t) noexcept { release(pointer); }
void operator delete[](void* pointer, std::size_t, std::align_val_t) noexcept { release(pointer); }
void operator delete(void* pointer, std::align_val_t, const std::nothrow_t&) noexcept { release(pointer); }
void operator delete[](void* pointer, std::align_val_t, const std::nothrow_t&) noexcept { release(pointer); }
#endif  // LANCER_KEEP_SANITIZER_ALLOCATOR
