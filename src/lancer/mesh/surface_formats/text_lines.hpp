// Line-by-line reading of the text surface formats (ASCII STL, OBJ, ASCII PLY): blank-separated
// tokens, numbers, and errors at the user's file:line:column.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "lancer/util/input_error.hpp"

namespace lancer {

class TextLines {
 public:
  // bytes from `begin` on are read, their first line numbered `firstLine`.
  TextLines(std::span<const char> bytes, std::string name, std::size_t begin = 0, std::int64_t firstLine = 1);

  // Moves to the next line (the first, at the start); false when the bytes are all read.
  bool nextLine();
  std::int64_t lineNumber() const { return line_; }
  // The next blank-separated token of the line, "" at its end.
  std::string_view token();
  bool atLineEnd();
  // What is left of the line, blanks trimmed at both ends.
  std::string_view restOfLine();
  // The next token as a finite number; `what` names it in messages ("the x coordinate of a vertex").
  double readNumber(const char* what);
  // The next token as an integer (a sign allowed).
  std::int64_t readInteger(const char* what);
  // Where the next line starts: the first byte after the current one.
  std::size_t nextLineOffset() const { return static_cast<std::size_t>(lineEnd_ - begin_) + lineBreak_; }
  const std::string& name() const { return name_; }
  // The 1-based column of the token last read.
  std::int64_t tokenColumn() const { return tokenStart_ - lineStart_ + 1; }

  // At the token last read (or the line's start when none was read yet).
  [[noreturn]] void fail(const std::string& message) const;
  [[noreturn]] void failAtLine(const std::string& message) const;
  // An error at the end of the file (what was still expected when it ended).
  [[noreturn]] void failAtEnd(const std::string& message) const;

 private:
  const char* begin_;
  const char* end_;
  const char* lineStart_;
  const char* lineEnd_;
  const char* pos_;
  const char* tokenStart_;
  std::size_t lineBreak_ = 0;
  std::int64_t line_;
  bool started_ = false;
  std::string name_;
};

}  // namespace lancer
