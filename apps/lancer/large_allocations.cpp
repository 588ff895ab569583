// The CLI's C++ allocations of a megabyte and more (a mesh's arrays, the scene's, the accelerator's
// build buffers and tree) on transparent huge pages (util/huge_page_blocks.hpp says why), through
// C++'s own mechanism for it: the replacement of the global operator new and delete. Only the
// executable links this file; the library, its tests and the Python module keep the defaults.
#include "large_allocations.hpp"

#include <unistd.h>

#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <new>
#include <string>

#include "lancer/util/huge_page_blocks.hpp"

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

// Says that the run was started by tuneMallocForHugePages, with the user's GLIBC_TUNABLES after
// the '=' ("-" when it was not set).
constexpr const char* kTunedMarker = "LANCER_MALLOC_TUNED";

bool transparentHugePagesOff() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  return !std::getline(in, line) || line.find("[never]") != std::string::npos;
}

}  // namespace

namespace lancer::cli {

void tuneMallocForHugePages(char** argv) {
  if (const char* marker = std::getenv(kTunedMarker)) {
    const std::string user = marker;
    if (user == "-")
      ::unsetenv("GLIBC_TUNABLES");
    else
      ::setenv("GLIBC_TUNABLES", user.c_str(), 1);
    ::unsetenv(kTunedMarker);
    return;
  }
  const char* given = std::getenv("GLIBC_TUNABLES");
  const std::string user = given ? given : "";
  if (user.find("glibc.malloc.hugetlb") != std::string::npos || transparentHugePagesOff()) return;
  const std::string tuned =
      (user.empty() ? "" : user + ":") + "glibc.malloc.hugetlb=1:glibc.malloc.top_pad=67108864";
  ::setenv(kTunedMarker, given ? user.c_str() : "-", 1);
  ::setenv("GLIBC_TUNABLES", tuned.c_str(), 1);
  ::execv("/proc/self/exe", argv);
  // Not run again (no /proc): on as before.
  ::unsetenv(kTunedMarker);
  if (given)
    ::setenv("GLIBC_TUNABLES", user.c_str(), 1);
  else
    ::unsetenv("GLIBC_TUNABLES");
}

}  // namespace lancer::cli

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
