// The memory budget behind --max-memory: size parsing, message formatting and the check itself.
#include "lancer/util/memory_budget.hpp"

#include <gtest/gtest.h>

namespace lancer {
namespace {

TEST(MemoryBudget, ParsesSizesWithBinaryUnits) {
  EXPECT_EQ(parseByteSize("123456"), 123456u);
  EXPECT_EQ(parseByteSize("1K"), 1024u);
  EXPECT_EQ(parseByteSize("512M"), 512ull << 20);
  EXPECT_EQ(parseByteSize("8G"), 8ull << 30);
  EXPECT_EQ(parseByteSize("8GiB"), 8ull << 30);
  EXPECT_EQ(parseByteSize("8GB"), 8ull << 30);
  EXPECT_EQ(parseByteSize("1.5T"), 3ull << 39);
  EXPECT_EQ(parseByteSize("100B"), 100u);
}

TEST(MemoryBudget, PercentIsOfPhysicalMemory) {
  if (physicalMemoryBytes() == 0) GTEST_SKIP() << "physical memory size unknown here";
  const auto half = parseByteSize("50%");
  ASSERT_TRUE(half);
  EXPECT_NEAR(static_cast<double>(*half), physicalMemoryBytes() / 2.0, 1.0);
  EXPECT_FALSE(parseByteSize("101%"));
}

TEST(MemoryBudget, RefusesWhatIsNotASize) {
  for (const char* bad : {"", "0", "-1G", "+1G", "G", "1X", "1.5.5G", "nan", "inf", "1e30T", "0.0001", "1 G"})
    EXPECT_FALSE(parseByteSize(bad)) << bad;
}

TEST(MemoryBudget, FormatsBytesForMessages) {
  EXPECT_EQ(formatBytes(900), "900 bytes");
  EXPECT_EQ(formatBytes(1024), "1.0 KiB");
  EXPECT_EQ(formatBytes(3ull << 29), "1.5 GiB");
  EXPECT_EQ(formatBytes(UINT64_MAX), "16.0 EiB");
}

TEST(MemoryBudget, DefaultIsThreeQuartersOfPhysicalMemory) {
  if (physicalMemoryBytes() == 0) GTEST_SKIP() << "physical memory size unknown here";
  EXPECT_EQ(defaultMemoryBudget(), physicalMemoryBytes() / 4 * 3);
}

TEST(MemoryBudget, RequireMemoryThrowsALocatedErrorOverTheBudget) {
  const std::uint64_t saved = memoryBudget();
  setMemoryBudget(1 << 20);
  EXPECT_NO_THROW(requireMemory(1 << 20, SourceLocation{"a.msh", 3, 1}, "x"));
  try {
    requireMemory(3ull << 30, SourceLocation{"a.msh", 3, 1}, "$Nodes with 50331648 entries");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(
        e.what(),
        "a.msh:3:1: error: $Nodes with 50331648 entries needs 3.0 GiB, more than the memory budget of "
        "1.0 MiB; use a smaller input or raise --max-memory");
  }
  setMemoryBudget(saved);
}

TEST(MemoryBudget, SaturatingProductNeverWraps) {
  EXPECT_EQ(saturatingProduct(1ull << 40, 64), 1ull << 46);
  EXPECT_EQ(saturatingProduct(1ull << 60, 64), UINT64_MAX);
  EXPECT_EQ(saturatingProduct(0, UINT64_MAX), 0u);
}

}  // namespace
}  // namespace lancer
