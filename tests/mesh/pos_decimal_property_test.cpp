// The .pos reader's fast decimal parse gives std::from_chars's double, to the bit, and stops where
// from_chars stops, on every number it takes: random doubles printed as solvers print them (%.16g,
// %.17g, %g, %e, fixed) and hand-picked edges; what it leaves (false) from_chars reads instead.
#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>

#include "lancer/mesh/msh/text_number.hpp"

namespace lancer {
namespace {

// Checks one text; returns whether the fast path took it.
bool expectSameAsFromChars(const std::string& text) {
  const char* end = text.data() + text.size();
  const char* fast = text.data();
  double fastValue = 0;
  const bool taken = readDecimalFast(fast, end, fastValue);
  if (!taken) {
    EXPECT_EQ(fast, text.data()) << text;  // left where it was
    return false;
  }
  double expected = 0;
  const auto [next, error] = std::from_chars(text.data(), end, expected);
  EXPECT_EQ(error, std::errc()) << text;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(fastValue), std::bit_cast<std::uint64_t>(expected))
      << text << ": " << fastValue << " against " << expected;
  EXPECT_EQ(fast - text.data(), next - text.data()) << text;
  return true;
}

std::string printed(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

TEST(PosDecimalProperty, RandomDoublesAsSolversPrintThem) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> scale(-30, 30);
  const char* formats[] = {"%.16g", "%.17g", "%g", "%.6e", "%.10f", "%.15e"};
  int taken = 0, total = 0;
  for (int i = 0; i < 100000; ++i) {
    const double value = unit(rng) * std::pow(10.0, scale(rng));
    for (const char* format : formats) {
      // Followed by the separators a list has, so that the stop is checked too.
      taken += expectSameAsFromChars(printed(format, value) + ",1");
      ++total;
    }
  }
  // Most of what a solver prints takes the fast path.
  EXPECT_GT(taken, total / 2);
}

TEST(PosDecimalProperty, Edges) {
  const char* taken[] = {"0",          "-0",   "0.",
                         ".5",         "-.5",  "00012",
                         "1.5e",       "1e+",  "1e-",
                         "2E+05",      "1e22", "1e-22",
                         "0.000123",   "-0e5", "9007199254740991",
                         "123.456e-3", "1.e5", "4.877771239555906e-05",
                         "7)",         "3}",   "0.001414427157001414"};
  for (const char* text : taken) EXPECT_TRUE(expectSameAsFromChars(text)) << text;
  const char* left[] = {"",      "-",     ".",
                        "+1",    "nan",   "inf",
                        "-inf",  "e5",    "9007199254740993",
                        "1e23",  "1e-23", "12345678901234567890",
                        "1e400", "0x10"};
  for (const char* text : left) {
    const std::string s = text;
    const char* p = s.data();
    double value = 0;
    const bool fast = readDecimalFast(p, s.data() + s.size(), value);
    // "0x10" is the 0 from_chars reads too, stopping at the 'x'.
    EXPECT_EQ(fast, s == "0x10") << text;
    if (fast) expectSameAsFromChars(s);
  }
}

}  // namespace
}  // namespace lancer
