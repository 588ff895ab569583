// The sample streams' Sobol' points: the byte tables give the direction numbers' definition, and
// every prefix of 2^k points of a pair of dimensions is stratified.
#include "lancer/render/sample_sequence.hpp"

#include <gtest/gtest.h>

#include <set>

namespace lancer {
namespace {

// Sobol' dimension 1 by its definition: the XOR of the direction numbers of the index's set bits.
std::uint32_t sobolDimension1(std::uint32_t index) {
  std::uint32_t y = 0;
  for (std::uint32_t v = 0x80000000u; index != 0; index >>= 1, v ^= v >> 1)
    if (index & 1u) y ^= v;
  return y;
}

TEST(SampleSequence, ByteTablesGiveTheDirectionNumbersDefinition) {
  std::uint32_t index = 0;
  for (int i = 0; i < 20000; ++i) {
    // Small indices, single bits, and hashed (scrambled-looking) ones.
    for (const std::uint32_t candidate : {static_cast<std::uint32_t>(i), 1u << (i % 32), index}) {
      std::uint32_t x, y;
      sobol::sobol2d(candidate, x, y);
      ASSERT_EQ(y, sobolDimension1(candidate)) << candidate;
      ASSERT_EQ(x, sobol::reverseBits(candidate)) << candidate;
    }
    index = hashBits(index + 0x9E3779B9u);
  }
}

TEST(SampleSequence, EveryPrefixOfAPowerOfTwoIsStratified) {
  // The first 16 samples of a pixel's first pair: one in each cell of a 4 x 4 grid.
  std::set<int> cells;
  for (std::uint32_t n = 0; n < 16; ++n) {
    SampleStream stream(5, 9, n);
    float u, v;
    stream.next2D(u, v);
    cells.insert(static_cast<int>(u * 4) * 4 + static_cast<int>(v * 4));
  }
  EXPECT_EQ(cells.size(), 16u);
}

}  // namespace
}  // namespace lancer
