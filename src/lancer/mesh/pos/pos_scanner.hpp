// The tokens of gmsh's .pos text (gmsh's lexer, Gmsh.l): numbers, names, "strings", punctuation,
// whitespace and // or /* */ comments between any two of them. Lines are counted as the scan goes,
// so an element knows its line for free; errors point at file:line:col.
#pragma once

#include <charconv>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "lancer/mesh/msh/text_number.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

class PosScanner {
 public:
  PosScanner(std::span<const char> bytes, std::string file)
      : begin_(bytes.data()),
        pos_(bytes.data()),
        end_(bytes.data() + bytes.size()),
        numberStart_(bytes.data()),
        file_(std::move(file)) {}

  const std::string& file() const { return file_; }
  const char* position() const { return pos_; }
  std::int64_t line() const { return line_; }
  bool atEnd() const { return pos_ >= end_; }
  std::size_t remainingBytes() const { return static_cast<std::size_t>(end_ - pos_); }
  std::span<const char> bytes() const { return {begin_, static_cast<std::size_t>(end_ - begin_)}; }
  // Where the last number() began (for messages about it).
  const char* numberStart() const { return numberStart_; }
  // Moves to `at` (a copy's way to describe a token it has passed; lines are not recounted).
  void seekTo(const char* at) { pos_ = at; }
  // Moves to `at`, on `line` (where another scan of the same bytes stopped).
  void seekTo(const char* at, std::int64_t line) {
    pos_ = at;
    line_ = line;
  }

  // Skips whitespace and comments (the hot case, a number right here, costs two compares).
  void skipSpace() {
    while (pos_ < end_) {
      const auto c = static_cast<unsigned char>(*pos_);
      if (!isTextSpace(*pos_) && c != '/') return;
      if (c == '/') {
        if (!skipComment()) return;
      } else {
        if (c == '\n') ++line_;
        ++pos_;
      }
    }
  }
  // The next character after whitespace and comments (control characters count as whitespace, as
  // in the .msh reader), or '\0' at the end of the file.
  char peek() {
    skipSpace();
    return pos_ < end_ ? *pos_ : '\0';
  }
  // Consumes `c` when it comes next.
  bool accept(char c) {
    if (peek() != c) return false;
    ++pos_;
    return true;
  }
  // A name ([A-Za-z_][A-Za-z0-9_]*) after whitespace; empty when none comes next.
  std::string_view name();
  // A "string" (gmsh's \-escapes undone); throws when none comes next.
  std::string quotedString(std::string_view context);

  // A number after whitespace (what C's strtod reads, without hex; a leading '+' allowed). Throws,
  // naming `context` ("in the values of this ST element"), when there is none or it is NaN or infinite.
  [[gnu::always_inline]] double number(std::string_view context) {
    skipSpace();
    numberStart_ = pos_;
    const char* p = pos_;
    double value;
    if (readDecimalFast(p, end_, value)) {
      pos_ = p;
      return value;
    }
    return otherNumber(context);
  }
  // Consumes `c` when it comes next (the hot case: right here, after a number).
  bool acceptNext(char c) {
    if (pos_ < end_ && *pos_ == c) {
      ++pos_;
      return true;
    }
    return accept(c);
  }

  // --- errors -----------------------------------------------------------------------------------
  SourceLocation locate(const char* at) const;
  [[noreturn]] void failAt(const char* at, const std::string& message) const;
  [[noreturn]] void fail(const std::string& message) const { failAt(pos_, message); }
  // "expected <what> <context>, found 'x'" (or "found the end of the file ...") at the next token.
  [[noreturn]] void failExpected(std::string_view what, std::string_view context);
  // What comes next, for messages: "'ST3'", "','", "the end of the file".
  std::string describeNext();

 private:
  bool skipComment();
  // What readDecimalFast leaves: long mantissas, large exponents, a leading '+', and what is no number.
  double otherNumber(std::string_view context);

  const char* begin_;
  const char* pos_;
  const char* end_;
  const char* numberStart_ = nullptr;
  std::string file_;
  std::int64_t line_ = 1;
};

}  // namespace lancer
