#include "lancer/mesh/surface_formats/text_lines.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstring>

#include "lancer/mesh/msh/text_number.hpp"

namespace lancer {

TextLines::TextLines(std::span<const char> bytes, std::string name, std::size_t begin, std::int64_t firstLine)
    : begin_(bytes.data()),
      end_(bytes.data() + bytes.size()),
      lineStart_(bytes.data() + begin),
      lineEnd_(bytes.data() + begin),
      pos_(bytes.data() + begin),
      tokenStart_(bytes.data() + begin),
      line_(firstLine - 1),
      name_(std::move(name)) {}

bool TextLines::nextLine() {
  const char* start = started_ ? lineEnd_ + lineBreak_ : lineStart_;
  started_ = true;
  if (start >= end_) {
    lineStart_ = lineEnd_ = pos_ = tokenStart_ = end_;
    lineBreak_ = 0;
    return false;
  }
  const void* newline = std::memchr(start, '\n', static_cast<std::size_t>(end_ - start));
  lineStart_ = start;
  lineEnd_ = newline ? static_cast<const char*>(newline) : end_;
  lineBreak_ = newline ? 1 : 0;
  pos_ = tokenStart_ = start;
  ++line_;
  return true;
}

bool TextLines::atLineEnd() {
  while (pos_ < lineEnd_ && isTextSpace(*pos_)) ++pos_;
  return pos_ == lineEnd_;
}

std::string_view TextLines::token() {
  atLineEnd();
  tokenStart_ = pos_;
  while (pos_ < lineEnd_ && !isTextSpace(*pos_)) ++pos_;
  return {tokenStart_, static_cast<std::size_t>(pos_ - tokenStart_)};
}

std::string_view TextLines::restOfLine() {
  atLineEnd();
  tokenStart_ = pos_;
  const char* last = lineEnd_;
  while (last > pos_ && isTextSpace(last[-1])) --last;
  pos_ = lineEnd_;
  return {tokenStart_, static_cast<std::size_t>(last - tokenStart_)};
}

double TextLines::readNumber(const char* what) {
  const std::string_view text = token();
  if (text.empty()) fail(fmt::format("expected {} (a number), found the end of the line", what));
  double value = 0;
  const char* first = text.data() + (text.front() == '+');  // from_chars takes no '+'
  const auto [next, error] = readTextDouble(first, text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range)
    fail(fmt::format("{} {} is out of range", what, quoteTokenForMessage(text)));
  if (error != std::errc() || next != text.data() + text.size())
    fail(fmt::format("expected {} (a number), found {}", what, quoteTokenForMessage(text)));
  if (!std::isfinite(value))
    fail(fmt::format("{} is {}: expected a finite number", what, quoteTokenForMessage(text)));
  return value;
}

std::int64_t TextLines::readInteger(const char* what) {
  const std::string_view text = token();
  if (text.empty()) fail(fmt::format("expected {} (an integer), found the end of the line", what));
  std::int64_t value = 0;
  const char* first = text.data() + (text.front() == '+');
  const auto [next, error] = std::from_chars(first, text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range)
    fail(fmt::format("{} {} is out of range", what, quoteTokenForMessage(text)));
  if (error != std::errc() || next != text.data() + text.size())
    fail(fmt::format("expected {} (an integer), found {}", what, quoteTokenForMessage(text)));
  return value;
}

void TextLines::fail(const std::string& message) const {
  throw InputError(SourceLocation{name_, line_, tokenStart_ - lineStart_ + 1}, message);
}

void TextLines::failAtLine(const std::string& message) const {
  throw InputError(SourceLocation{name_, line_}, message);
}

void TextLines::failAtEnd(const std::string& message) const {
  // The last line of the file: the one read last, as editors number it.
  throw InputError(SourceLocation{name_, std::max<std::int64_t>(line_, 1)}, message);
}

}  // namespace lancer
