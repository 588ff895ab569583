// A process-wide memory budget (the CLI's --max-memory): readers and the CLI check the memory an input
// asks for before allocating it, so a huge or lying input fails with a clear message instead of being
// killed by the operating system's out-of-memory killer.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "lancer/util/input_error.hpp"

namespace lancer {

// Total physical memory (sysconf), or 0 when unknown.
std::uint64_t physicalMemoryBytes();

// The default budget: 3/4 of physical memory (what is left keeps the desktop and the page cache
// alive), or 16 GiB when the size of physical memory is unknown.
std::uint64_t defaultMemoryBudget();

// The current budget in bytes (defaultMemoryBudget() until set). Thread-safe.
std::uint64_t memoryBudget();
void setMemoryBudget(std::uint64_t bytes);

// Parses "512M", "8G", "8GiB", "1.5T", "123456" (bytes) or "50%" (of physical memory); K, M, G, T are
// binary (1024-based). std::nullopt for anything else, zero included.
std::optional<std::uint64_t> parseByteSize(std::string_view text);

// "1.5 GiB", "512 MiB", "900 bytes": for messages.
std::string formatBytes(std::uint64_t bytes);

// Throws InputError at `where` when `bytes` exceed the budget:
//   "<where>: error: <what> needs 64.0 GiB, more than the memory budget of 12.0 GiB; use a smaller
//    input or raise --max-memory"
void requireMemory(std::uint64_t bytes, const SourceLocation& where, std::string_view what);

// count * itemBytes, saturating at UINT64_MAX instead of wrapping (for counts read from files).
constexpr std::uint64_t saturatingProduct(std::uint64_t count, std::uint64_t itemBytes) {
  if (itemBytes != 0 && count > UINT64_MAX / itemBytes) return UINT64_MAX;
  return count * itemBytes;
}

}  // namespace lancer
