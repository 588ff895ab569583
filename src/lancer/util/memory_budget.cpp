#include "lancer/util/memory_budget.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdlib>

namespace lancer {
namespace {

// 0 means "not set": the default is computed on first use.
std::atomic<std::uint64_t> gBudget{0};

}  // namespace

std::uint64_t physicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || pageSize <= 0) return 0;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(pageSize);
}

std::uint64_t defaultMemoryBudget() {
  const std::uint64_t physical = physicalMemoryBytes();
  return physical == 0 ? std::uint64_t{16} << 30 : physical / 4 * 3;
}

std::uint64_t memoryBudget() {
  const std::uint64_t budget = gBudget.load(std::memory_order_relaxed);
  return budget != 0 ? budget : defaultMemoryBudget();
}

void setMemoryBudget(std::uint64_t bytes) { gBudget.store(bytes, std::memory_order_relaxed); }

std::optional<std::uint64_t> parseByteSize(std::string_view text) {
  const std::string copy(text);
  const char* begin = copy.c_str();
  char* end = nullptr;
  const double number = std::strtod(begin, &end);
  if (end == begin || !std::isfinite(number) || !(number > 0) || *begin == '-' || *begin == '+')
    return std::nullopt;
  std::string_view unit(end);
  double scale = 1;
  if (unit == "%") {
    if (number > 100) return std::nullopt;
    const std::uint64_t physical = physicalMemoryBytes();
    if (physical == 0) return std::nullopt;
    scale = static_cast<double>(physical) / 100;
  } else {
    if (unit.ends_with("iB"))
      unit.remove_suffix(2);
    else if (unit.size() == 2 && unit.back() == 'B')
      unit.remove_suffix(1);
    if (unit == "K" || unit == "k")
      scale = 1024.0;
    else if (unit == "M")
      scale = 1024.0 * 1024;
    else if (unit == "G")
      scale = 1024.0 * 1024 * 1024;
    else if (unit == "T")
      scale = 1024.0 * 1024 * 1024 * 1024;
    else if (!unit.empty() && unit != "B")
      return std::nullopt;
  }
  const double bytes = std::floor(number * scale);
  if (bytes < 1 || bytes >= 1.8e19) return std::nullopt;
  return static_cast<std::uint64_t>(bytes);
}

std::string formatBytes(std::uint64_t bytes) {
  constexpr const char* kUnits[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  if (bytes < 1024) return fmt::format("{} bytes", bytes);
  double value = static_cast<double>(bytes) / 1024;
  int unit = 0;
  while (value >= 1024 && unit < 5) {
    value /= 1024;
    ++unit;
  }
  return fmt::format("{:.1f} {}", value, kUnits[unit]);
}

void requireMemory(std::uint64_t bytes, const SourceLocation& where, std::string_view what) {
  const std::uint64_t budget = memoryBudget();
  if (bytes <= budget) return;
  throw InputError(where,
                   fmt::format("{} needs {}, more than the memory budget of {}; use a smaller input or "
                               "raise --max-memory",
                               what, formatBytes(bytes), formatBytes(budget)));
}

}  // namespace lancer
