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

TEST(HugePageBlocks, AReleasedBlockIsNoLongerOneAndAnImpossibleSizeIsRefused) {
  void* first = allocateLargeBlock(kLargeBlockBytes);
  ASSERT_NE(first, nullptr);
  void* second = allocateLargeBlock(kLargeBlockBytes);
  ASSERT_NE(second, nullptr);
  EXPECT_NE(first, second);
  releaseLargeBlock(first);
  EXPECT_FALSE(isLargeBlock(first));
  EXPECT_TRUE(isLargeBlock(second));
  releaseLargeBlock(second);
  EXPECT_EQ(allocateLargeBlock(SIZE_MAX - 100), nullptr);
  releaseRetainedLargeBlocks();
}

TEST(HugePageBlocks, AReleasedBlockIsKeptAndTakenAgainBySameSize) {
  releaseRetainedLargeBlocks();
  const LargeBlockStats before = largeBlockStats();
  EXPECT_EQ(before.retainedBytes, 0u);
  void* block = allocateLargeBlock(3 * kHugePage);
  ASSERT_NE(block, nullptr);
  const std::size_t mapped = largeBlockMappedBytes(block);
  EXPECT_EQ(mapped, 4 * kHugePage);  // the header needs a page more
  LargeBlockStats stats = largeBlockStats();
  EXPECT_EQ(stats.inUseBytes, before.inUseBytes + mapped);
  EXPECT_EQ(stats.mappedBlocks, before.mappedBlocks + 1);
  EXPECT_GE(stats.peakMappedBytes, stats.inUseBytes);
  static_cast<char*>(block)[0] = 42;
  releaseLargeBlock(block);
  stats = largeBlockStats();
  EXPECT_EQ(stats.inUseBytes, before.inUseBytes);
  EXPECT_EQ(stats.retainedBytes, mapped);

  // The same request takes it again: no block mapped, its bytes as left.
  void* again = allocateLargeBlock(3 * kHugePage);
  EXPECT_EQ(again, block);
  EXPECT_EQ(static_cast<char*>(again)[0], 42);
  EXPECT_EQ(largeBlockMappedBytes(again), mapped);
  stats = largeBlockStats();
  EXPECT_EQ(stats.mappedBlocks, before.mappedBlocks + 1);
  EXPECT_EQ(stats.reusedBlocks, before.reusedBlocks + 1);
  EXPECT_EQ(stats.retainedBytes, 0u);
  EXPECT_EQ(stats.inUseBytes, before.inUseBytes + mapped);
  releaseLargeBlock(again);

  releaseRetainedLargeBlocks();
  stats = largeBlockStats();
  EXPECT_EQ(stats.retainedBytes, 0u);
  EXPECT_EQ(stats.unmappedBlocks, before.unmappedBlocks + 1);
}

TEST(HugePageBlocks, AKeptBlockTooLargeIsCutAndOneTooSmallMakesRoom) {
  releaseRetainedLargeBlocks();
  const LargeBlockStats before = largeBlockStats();
  // Kept: two blocks of 2 MiB and one of 16 MiB (each with its header).
  void* small1 = allocateLargeBlock(kLargeBlockBytes);
  void* small2 = allocateLargeBlock(kLargeBlockBytes);
  void* large = allocateLargeBlock(8 * kHugePage - kLargeBlockAlignment);
  ASSERT_TRUE(small1 && small2 && large);
  const std::size_t peak = largeBlockStats().peakMappedBytes;
  releaseLargeBlock(small1);
  releaseLargeBlock(small2);
  releaseLargeBlock(large);
  EXPECT_EQ(largeBlockStats().retainedBytes, 10 * kHugePage);

  // 6 MiB: the 16 MiB block is the one that fits, cut to the request: its end goes back.
  void* middle = allocateLargeBlock(3 * kHugePage - kLargeBlockAlignment);
  EXPECT_EQ(middle, large);
  EXPECT_EQ(largeBlockMappedBytes(middle), 3 * kHugePage);
  LargeBlockStats stats = largeBlockStats();
  EXPECT_EQ(stats.mappedBlocks, before.mappedBlocks + 3);
  EXPECT_EQ(stats.reusedBlocks, before.reusedBlocks + 1);
  EXPECT_EQ(stats.retainedBytes, 2 * kHugePage);
  EXPECT_EQ(stats.inUseBytes, before.inUseBytes + 3 * kHugePage);

  // 10 MiB: no kept block fits; both are moved into it before any page is mapped fresh, so the
  // memory mapped does not pass the earlier peak.
  void* big = allocateLargeBlock(5 * kHugePage - kLargeBlockAlignment);
  ASSERT_NE(big, nullptr);
  stats = largeBlockStats();
  EXPECT_EQ(stats.mappedBlocks, before.mappedBlocks + 4);
  EXPECT_EQ(stats.movedBlocks, before.movedBlocks + 2);
  EXPECT_EQ(stats.unmappedBlocks, before.unmappedBlocks);
  EXPECT_EQ(stats.retainedBytes, 0u);
  EXPECT_EQ(stats.peakMappedBytes, peak);
  std::memset(middle, 1, 3 * kHugePage - kLargeBlockAlignment);  // still whole
  releaseLargeBlock(middle);
  releaseLargeBlock(big);
  releaseRetainedLargeBlocks();
  EXPECT_EQ(largeBlockStats().retainedBytes, 0u);
  EXPECT_EQ(largeBlockStats().inUseBytes, before.inUseBytes);
}

// Marks each 2 MiB page of a block (past its header) with `mark` plus the page's number.
void markPages(void* block, std::size_t pages, unsigned char mark) {
  auto* base = static_cast<unsigned char*>(block) - kLargeBlockAlignment;
  for (std::size_t page = 0; page < pages; ++page) base[page * kHugePage + 100] = mark + page;
}

TEST(HugePageBlocks, ARequestNoKeptBlockFitsIsMadeOfKeptPagesMovedNotCleared) {
  releaseRetainedLargeBlocks();
  const LargeBlockStats before = largeBlockStats();
  // Kept: 6 MiB and 4 MiB, each page marked.
  void* six = allocateLargeBlock(3 * kHugePage - kLargeBlockAlignment);
  void* four = allocateLargeBlock(2 * kHugePage - kLargeBlockAlignment);
  ASSERT_TRUE(six && four);
  markPages(six, 3, 10);
  markPages(four, 2, 20);
  const std::size_t peak = largeBlockStats().peakMappedBytes;
  releaseLargeBlock(six);
  releaseLargeBlock(four);

  // 8 MiB: the 6 MiB block's pages first (the largest), then the 4 MiB one's first page; its
  // second goes back to the system. No page is mapped fresh, none cleared.
  void* eight = allocateLargeBlock(4 * kHugePage - kLargeBlockAlignment);
  ASSERT_NE(eight, nullptr);
  EXPECT_TRUE(isLargeBlock(eight));
  EXPECT_EQ(largeBlockMappedBytes(eight), 4 * kHugePage);
  const auto* base = static_cast<const unsigned char*>(eight) - kLargeBlockAlignment;
  EXPECT_EQ(base[0 * kHugePage + 100], 10);
  EXPECT_EQ(base[1 * kHugePage + 100], 11);
  EXPECT_EQ(base[2 * kHugePage + 100], 12);
  EXPECT_EQ(base[3 * kHugePage + 100], 20);
  LargeBlockStats stats = largeBlockStats();
  EXPECT_EQ(stats.mappedBlocks, before.mappedBlocks + 2);  // six and four only
  EXPECT_EQ(stats.movedBlocks, before.movedBlocks + 2);
  EXPECT_EQ(stats.retainedBytes, 0u);
  EXPECT_EQ(stats.inUseBytes, before.inUseBytes + 4 * kHugePage);
  EXPECT_EQ(stats.peakMappedBytes, peak);
  std::memset(eight, 3, 4 * kHugePage - kLargeBlockAlignment);  // every byte writable

  // Taken again whole by the same size, and a block past it moves it and maps the rest fresh.
  releaseLargeBlock(eight);
  void* twelve = allocateLargeBlock(6 * kHugePage - kLargeBlockAlignment);
  ASSERT_NE(twelve, nullptr);
  EXPECT_EQ(static_cast<const unsigned char*>(twelve)[0], 3);
  EXPECT_EQ(static_cast<const unsigned char*>(twelve)[4 * kHugePage - kLargeBlockAlignment - 1], 3);
  stats = largeBlockStats();
  EXPECT_EQ(stats.mappedBlocks, before.mappedBlocks + 3);
  EXPECT_EQ(stats.movedBlocks, before.movedBlocks + 3);
  std::memset(twelve, 4, 6 * kHugePage - kLargeBlockAlignment);
  releaseLargeBlock(twelve);
  releaseRetainedLargeBlocks();
  EXPECT_EQ(largeBlockStats().inUseBytes, before.inUseBytes);
}

}  // namespace
}  // namespace lancer
