#include "lancer/util/morton_order.hpp"

#include <array>
#include <utility>

#include "lancer/util/huge_pages.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer {

namespace {
constexpr int kDigitBits = 10;  // three passes over the 30-bit code
constexpr std::size_t kDigits = std::size_t(1) << kDigitBits;
}  // namespace

// Least significant digit first, each pass a histogram per chunk, the chunks' offsets in chunk
// order, and a scatter per chunk.
std::uint64_t* sortMortonKeys(std::uint64_t* keys, std::uint64_t* scratch, std::size_t count, int threads) {
  const ChunkPlan plan(count, 1 << 15);
  std::vector<std::array<std::uint32_t, kDigits>> offsets(plan.chunks);
  for (int shift = 32; shift < 32 + 3 * kMortonBitsPerAxis; shift += kDigitBits) {
    auto digit = [shift](std::uint64_t key) { return (key >> shift) & (kDigits - 1); };
    parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      std::array<std::uint32_t, kDigits>& tally = offsets[chunk];
      tally.fill(0);
      for (std::size_t i = begin; i < end; ++i) ++tally[digit(keys[i])];
    });
    std::uint32_t sum = 0;
    for (std::size_t d = 0; d < kDigits; ++d) {
      for (std::size_t c = 0; c < plan.chunks; ++c) {
        const std::uint32_t tally = offsets[c][d];
        offsets[c][d] = sum;
        sum += tally;
      }
    }
    parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      std::array<std::uint32_t, kDigits>& next = offsets[chunk];
      for (std::size_t i = begin; i < end; ++i) scratch[next[digit(keys[i])]++] = keys[i];
    });
    std::swap(keys, scratch);
  }
  return keys;
}

void sortMortonKeys(std::vector<std::uint64_t>& keys, int threads) {
  std::vector<std::uint64_t> other = vectorOnHugePages<std::uint64_t>(keys.size());
  if (sortMortonKeys(keys.data(), other.data(), keys.size(), threads) == other.data()) keys.swap(other);
}

}  // namespace lancer
