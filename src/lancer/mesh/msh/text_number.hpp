// The numbers and blanks of the text formats, one implementation for the .msh cursor and the .pos
// scanner: the decimal numbers solvers print (%.16g: "0.001414427157001414",
// "-4.877771239555906e-05") take a fast path, so their parse sets the speed of a text file.
// Digits are read eight at a time (SWAR, as in Lemire's fast_float, "Number Parsing at a Gigabyte
// per Second", 2021); a mantissa below 2^53 with a power of ten within 10^+-22 gives the correctly
// rounded double with one multiplication or division of two exact doubles (Clinger, "How to Read
// Floating Point Numbers Accurately", 1990). Anything else is left to std::from_chars.
#pragma once

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace lancer {

namespace decimal_detail {

inline constexpr double kPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                          1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                          1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

inline bool isDigit(char c) { return static_cast<unsigned char>(c - '0') < 10; }

inline constexpr std::uint64_t kIntegerPowersOfTen[] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000};

// The value of 8 ASCII digits, the first (lowest byte) the most significant.
inline std::uint32_t eightDigitValue(std::uint64_t bytes) {
  bytes -= 0x3030303030303030ull;
  bytes = bytes * 10 + (bytes >> 8);  // pairs of digits in every other byte
  const std::uint64_t pairs = bytes & 0x000000FF000000FFull;
  const std::uint64_t next = (bytes >> 16) & 0x000000FF000000FFull;
  return static_cast<std::uint32_t>((pairs * 0x000F424000000064ull + next * 0x0000271000000001ull) >> 32);
}

// Appends the digits at p (up to end) to `mantissa`, counting them; stops at the first non-digit.
// Eight bytes at a time: the first non-digit is the lowest byte flagged below (a carry or borrow
// only runs upwards, from a byte that is itself flagged), and the n digits before it are parsed as
// the eight digits "0...0" + those n, with no branch per digit.
inline void readDigits(const char*& p, const char* end, std::uint64_t& mantissa, int& digits) {
  while (end - p >= 8) {
    std::uint64_t bytes;
    std::memcpy(&bytes, p, 8);
    const std::uint64_t notDigit =
        ((bytes + 0x4646464646464646ull) | (bytes - 0x3030303030303030ull)) & 0x8080808080808080ull;
    if (notDigit == 0) {
      mantissa = mantissa * 100000000 + eightDigitValue(bytes);
      digits += 8;
      p += 8;
      continue;
    }
    const int n = std::countr_zero(notDigit) / 8;
    if (n > 0) {
      const std::uint64_t padded = (bytes << (8 * (8 - n))) | (0x3030303030303030ull >> (8 * n));
      mantissa = mantissa * kIntegerPowersOfTen[n] + eightDigitValue(padded);
      digits += n;
      p += n;
    }
    return;
  }
  while (p < end && isDigit(*p)) {
    mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
    ++digits;
    ++p;
  }
}

}  // namespace decimal_detail

// Reads [-]digits[.digits][(e|E)[+-]digits] at p into `value` and moves p past it; false (p
// unchanged) for what the fast path does not cover (more than 19 significant digits, a mantissa of
// 2^53 or more, an exponent beyond +-22, no digits, nan, inf), which std::from_chars then reads.
[[gnu::always_inline]] inline bool readDecimalFast(const char*& p, const char* end, double& value) {
  using namespace decimal_detail;
  const char* q = p;
  const bool negative = q < end && *q == '-';
  q += negative;
  while (q < end && *q == '0') ++q;  // leading zeros are not significant
  std::uint64_t mantissa = 0;
  int digits = 0;
  readDigits(q, end, mantissa, digits);
  bool anyDigit = q > p + negative;
  int exponent = 0;
  if (q < end && *q == '.') {
    ++q;
    const char* fractionStart = q;
    if (digits == 0)
      while (q < end && *q == '0') ++q;  // 0.000123: zeros before the first significant digit
    readDigits(q, end, mantissa, digits);
    exponent = -static_cast<int>(q - fractionStart);
    anyDigit = anyDigit || q > fractionStart;
  }
  if (!anyDigit || digits > 19) return false;
  if (q < end && (*q == 'e' || *q == 'E')) {
    const char* e = q + 1;
    const bool negativeExponent = e < end && *e == '-';
    e += (e < end && (*e == '-' || *e == '+'));
    if (e < end && isDigit(*e)) {  // "1.5e" ends before the 'e', as std::from_chars reads it
      int written = 0;
      while (e < end && isDigit(*e) && written < 10000) written = written * 10 + (*e++ - '0');
      if (e < end && isDigit(*e)) return false;
      exponent += negativeExponent ? -written : written;
      q = e;
    }
  }
  if (mantissa >= (std::uint64_t{1} << 53)) return false;
  double result = static_cast<double>(mantissa);
  if (mantissa != 0) {
    if (exponent < -22 || exponent > 22) return false;
    result = exponent < 0 ? result / kPowersOfTen[-exponent] : result * kPowersOfTen[exponent];
  }
  value = negative ? -result : result;
  p = q;
  return true;
}

// What std::from_chars reads into a double (no '+', no hex; nan and inf too), the same result,
// with the fast path above for the common case.
[[gnu::always_inline]] inline std::from_chars_result readTextDouble(const char* p, const char* end,
                                                                    double& value) {
  const char* q = p;
  if (readDecimalFast(q, end, value)) return {q, std::errc()};
  return std::from_chars(p, end, value);
}

// Blanks between tokens: space, tab, line ends and every other control character.
inline bool isTextSpace(char c) { return static_cast<unsigned char>(c) <= ' '; }

// What the user sees of a bad token in a message: at most 32 printable characters, in quotes.
std::string quoteTokenForMessage(std::string_view token);

}  // namespace lancer
