#include "lancer/util/huge_page_blocks.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace lancer {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

TEST(HugePageBlocks, LargeBlocksAreAlignedWholeAndTheirOwn) {
  for (const std::size_t bytes :
       {kLargeBlockBytes, kHugePage - kLargeBlockAlignment, kHugePage, 3 * kHugePage + 12345}) {
    void* block = allocateLargeBlock(bytes);
    ASSERT_NE(block, nullptr) << bytes;
    const auto address = reinterpret_cast<std::uintptr_t>(block);
    EXPECT_EQ(address % kLargeBlockAlignment, 0u);
    EXPECT_TRUE(isLargeBlock(block));
    // Whole 2 MiB pages, header included, and no more than one page past what was asked.
    const std::size_t mapped = largeBlockMappedBytes(block);
    EXPECT_EQ(mapped % kHugePage, 0u);
    EXPECT_GE(mapped, bytes + kLargeBlockAlignment);
    EXPECT_LT(mapped, bytes + kLargeBlockAlignment + kHugePage);
    std::memset(block, 0xAB, bytes);  // every byte is writable
    EXPECT_EQ(static_cast<unsigned char*>(block)[bytes - 1], 0xAB);
    releaseLargeBlock(block);
  }
}

TEST(HugePageBlocks, MallocBlocksAreNotTakenForLargeOnes) {
  // Blocks of every size malloc hands out, kept alive so that their addresses differ, including
  // some at the offset a large block has within its 2 MiB page when malloc happens to give one.
  std::vector<void*> blocks;
  for (std::size_t bytes = 1; bytes < (std::size_t{4} << 20); bytes = bytes * 3 / 2 + 1) {
    void* block = std::malloc(bytes);
    ASSERT_NE(block, nullptr);
    std::memset(block, 0, bytes < 256 ? bytes : 256);
    EXPECT_FALSE(isLargeBlock(block)) << bytes;
    EXPECT_EQ(largeBlockMappedBytes(block), 0u);
    blocks.push_back(block);
  }
  for (void* block : blocks) std::free(block);
}

TEST(HugePageBlocks, AReleasedBlockIsGoneAndAnImpossibleSizeIsRefused) {
  void* first = allocateLargeBlock(kLargeBlockBytes);
  ASSERT_NE(first, nullptr);
  void* second = allocateLargeBlock(kLargeBlockBytes);
  ASSERT_NE(second, nullptr);
  EXPECT_NE(first, second);
  releaseLargeBlock(first);
  EXPECT_TRUE(isLargeBlock(second));
  releaseLargeBlock(second);
  EXPECT_EQ(allocateLargeBlock(SIZE_MAX - 100), nullptr);
}

}  // namespace
}  // namespace lancer
