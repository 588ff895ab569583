#include "lancer/mesh/pos/pos_scanner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace lancer {
namespace {

bool isNameStart(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool isNameChar(char c) { return isNameStart(c) || (c >= '0' && c <= '9'); }
bool isSeparator(char c) { return isTextSpace(c) || std::strchr(",;(){}\"", c) != nullptr; }

}  // namespace

bool PosScanner::skipComment() {
  if (pos_ + 1 >= end_) return false;
  if (pos_[1] == '/') {
    const void* newline = std::memchr(pos_, '\n', static_cast<std::size_t>(end_ - pos_));
    pos_ = newline ? static_cast<const char*>(newline) : end_;
    return true;
  }
  if (pos_[1] != '*') return false;
  const char* start = pos_;
  for (const char* p = pos_ + 2; p + 1 < end_; ++p) {
    if (*p == '\n') ++line_;
    if (p[0] == '*' && p[1] == '/') {
      pos_ = p + 2;
      return true;
    }
  }
  failAt(start, "this /* comment is never closed: the file ends inside it (the file looks truncated)");
}

std::string_view PosScanner::name() {
  skipSpace();
  const char* start = pos_;
  if (pos_ < end_ && isNameStart(*pos_))
    while (pos_ < end_ && isNameChar(*pos_)) ++pos_;
  return {start, static_cast<std::size_t>(pos_ - start)};
}

std::string PosScanner::quotedString(std::string_view context) {
  if (peek() != '"') failExpected("a \"quoted\" name", context);
  const char* start = pos_++;
  std::string text;
  while (pos_ < end_ && *pos_ != '"') {
    if (*pos_ == '\n') ++line_;
    if (*pos_ == '\\' && pos_ + 1 < end_) ++pos_;
    text += *pos_++;
  }
  if (pos_ >= end_)
    failAt(start, "this string is never closed: the file ends inside it (the file looks truncated)");
  ++pos_;
  return text;
}

double PosScanner::otherNumber(std::string_view context) {
  const char* start = pos_;
  double value = 0;
  const auto [next, error] = std::from_chars(start + (start < end_ && *start == '+'), end_, value);
  if (error == std::errc() && value - value == 0) {
    pos_ = next;
    return value;
  }
  if (error == std::errc::invalid_argument) {
    pos_ = start;
    failExpected("a number", context);
  }
  const char* end = start;
  while (end < end_ && !isSeparator(*end)) ++end;
  const std::string token(start, end);
  if (error == std::errc::result_out_of_range) {
    // from_chars refuses what underflows as well as what overflows; strtod tells them apart, and a
    // value too small for a double is as good as zero to a colour map.
    const double tiny = std::strtod(token.c_str(), nullptr);
    if (std::isinf(tiny))
      failAt(start, fmt::format("the number {} {} is beyond the range of a double",
                                quoteTokenForMessage(token), context));
    pos_ = next;
    return tiny;
  }
  failAt(start, fmt::format("found {}, which is {}, {}: lancer reads finite numbers only; the solver "
                            "wrote no value here, check its solution",
                            quoteTokenForMessage(token),
                            std::isnan(value) ? "not a number (NaN)" : "infinite", context));
}

SourceLocation PosScanner::locate(const char* at) const {
  at = std::clamp(at, begin_, end_);
  SourceLocation location{file_};
  location.line = 1 + std::count(begin_, at, '\n');
  const char* lineStart = at;
  while (lineStart > begin_ && lineStart[-1] != '\n') --lineStart;
  location.column = 1 + (at - lineStart);
  return location;
}

void PosScanner::failAt(const char* at, const std::string& message) const {
  throw InputError(locate(at), message);
}

std::string PosScanner::describeNext() {
  skipSpace();
  if (pos_ >= end_) return "the end of the file";
  const char* end = pos_;
  if (isSeparator(*end)) return quoteTokenForMessage({pos_, 1});
  while (end < end_ && !isSeparator(*end)) ++end;
  return quoteTokenForMessage({pos_, static_cast<std::size_t>(end - pos_)});
}

void PosScanner::failExpected(std::string_view what, std::string_view context) {
  skipSpace();
  if (pos_ >= end_)
    fail(fmt::format("expected {} {}, found the end of the file (the file looks truncated)", what, context));
  fail(fmt::format("expected {} {}, found {}", what, context, describeNext()));
}

}  // namespace lancer
