#include "lancer/util/morton_order.hpp"

#include <array>

#include "lancer/util/huge_pages.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer {

namespace {
constexpr int kDigitBits = 10;  // three passes over the 30-bit code
constexpr std::size_t kDigits = std::size_t(1) << kDigitBits;
}  // namespace

// Least significant digit first, each pass a histogram per chunk, the chunks' offsets in chunk
// order, and a scatter per chunk.
void sortMortonKeys(std::vector<std::uint64_t>& keys, int threads) {
  std::vector<std::uint64_t> other = vectorOnHugePages<std::uint64_t>(keys.size());
  const ChunkPlan plan(keys.size(), 1 << 15);
  std::vector<std::array<std::uint32_t, kDigits>> offsets(plan.chunks);
  for (int shift = 32; shift < 32 + 3 * kMortonBitsPerAxis; shift += kDigitBits) {
    auto digit = [shift](std::uint64_t key) { return (key >> shift) & (kDigits - 1); };
    parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      std::array<std::uint32_t, kDigits>& count = offsets[chunk];
      count.fill(0);
      for (std::size_t i = begin; i < end; ++i) ++count[digit(keys[i])];
    });
    std::uint32_t sum = 0;
    for (std::size_t d = 0; d < kDigits; ++d) {
      for (std::size_t c = 0; c < plan.chunks; ++c) {
        const std::uint32_t count = offsets[c][d];
        offsets[c][d] = sum;
        sum += count;
      }
    }
    parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      std::array<std::uint32_t, kDigits>& next = offsets[chunk];
      for (std::size_t i = begin; i < end; ++i) other[next[digit(keys[i])]++] = keys[i];
    });
    keys.swap(other);
  }
}

}  // namespace lancer
