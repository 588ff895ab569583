// A read cursor over a memory-mapped .msh file: whitespace-separated numbers for the ASCII parts,
// raw little-endian values for the binary parts, and errors that point at the user's file
// (line:column for text, @byte-offset for binary). The hot functions are inline; errors are cold.
#pragma once

#include <charconv>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

#include "lancer/mesh/msh/text_number.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

// Memory a node or a face costs from reading to rendering: the reader's tag and coordinate tables,
// the mesh's positions and normals, the kd-tree's references. Estimated from the sizes of those
// tables (a node: 8 tag + 24 coordinates + 12 position + 12 normal + 4 index = 60 bytes; a face is
// less), rounded up so that the check errs on the side of a clear message.
inline constexpr std::uint64_t kMeshBytesPerItem = 64;

class MshCursor {
 public:
  MshCursor(std::span<const char> bytes, std::string file)
      : begin_(bytes.data()), pos_(bytes.data()), end_(bytes.data() + bytes.size()), file_(std::move(file)) {}

  const std::string& file() const { return file_; }
  const char* position() const { return pos_; }
  std::uint64_t offset() const { return static_cast<std::uint64_t>(pos_ - begin_); }
  std::uint64_t remaining() const { return static_cast<std::uint64_t>(end_ - pos_); }
  bool atEnd() const { return pos_ >= end_; }
  // From here on, errors give byte offsets (the file's data sections are binary).
  void setBinaryLocations(bool binary) { binaryLocations_ = binary; }

  // --- text -------------------------------------------------------------------------------------
  void skipWhitespace() {
    while (pos_ < end_ && isTextSpace(*pos_)) ++pos_;
  }
  // Where the next token starts (for error locations).
  const char* tokenStart() {
    skipWhitespace();
    return pos_;
  }
  // Skips the rest of the current line including its '\n' (used once after a binary header line).
  void skipLine() {
    const void* newline = std::memchr(pos_, '\n', static_cast<std::size_t>(end_ - pos_));
    pos_ = newline ? static_cast<const char*>(newline) + 1 : end_;
  }
  // The next whitespace-separated token; empty at the end of the file.
  std::string_view token() {
    skipWhitespace();
    const char* start = pos_;
    while (pos_ < end_ && !isTextSpace(*pos_)) ++pos_;
    return {start, static_cast<std::size_t>(pos_ - start)};
  }

  template <typename Int>
  Int readInt(const char* what) {
    skipWhitespace();
    Int value{};
    const auto [next, error] = std::from_chars(pos_, end_, value);
    if (error != std::errc() || !endsToken(next)) failNumber(what, error == std::errc::result_out_of_range);
    pos_ = next;
    return value;
  }
  std::int64_t readInt64(const char* what) { return readInt<std::int64_t>(what); }
  // A small count that is mostly one digit (an $ElementNodeData record's node count): that digit
  // without a call to from_chars (kept out of readInt, whose inlined from_chars the element lists
  // need).
  std::int64_t readShortInt64(const char* what) {
    skipWhitespace();
    if (end_ - pos_ >= 2 && static_cast<unsigned char>(pos_[0] - '0') < 10 && isTextSpace(pos_[1]))
      return *pos_++ - '0';
    return readInt<std::int64_t>(what);
  }
  int readInt32(const char* what) { return readInt<int>(what); }
  // A count or tag that may not be negative.
  std::uint64_t readCount(const char* what) {
    skipWhitespace();
    if (pos_ < end_ && *pos_ == '-') failNumber(what, false, "a non-negative integer");
    return readInt<std::uint64_t>(what);
  }
  double readDouble(const char* what) {
    skipWhitespace();
    double value = 0;
    const auto [next, error] = readTextDouble(pos_, end_, value);
    if (error != std::errc() || !endsToken(next))
      failNumber(what, error == std::errc::result_out_of_range, "a number");
    pos_ = next;
    return value;
  }

  // Reads a "$Name" token and checks it is `expected` (e.g. "$EndNodes").
  void expectToken(std::string_view expected, const char* context);

  // --- binary -----------------------------------------------------------------------------------
  // Throws unless count items of itemBytes each fit in what is left of the file (overflow-safe).
  void requireBytes(std::uint64_t count, std::uint64_t itemBytes, const char* what) const {
    if (itemBytes != 0 && count > remaining() / itemBytes) failTooFew(count, itemBytes, what);
  }
  template <typename T>
  T readRaw(const char* what) {
    static_assert(std::is_trivially_copyable_v<T>);
    requireBytes(1, sizeof(T), what);
    T value;
    std::memcpy(&value, pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }
  // Throws when count nodes or faces (kMeshBytesPerItem each once loaded, indexed and accelerated)
  // would exceed the memory budget (--max-memory); called before reserving from a count in the file.
  void requireMemory(std::uint64_t count, const char* what) const;
  // Copies count values of T; the caller has called requireBytes.
  template <typename T>
  void copyRaw(T* out, std::uint64_t count) {
    if (count == 0) return;  // out may be an empty vector's null data(): memcpy(nullptr, ...) is UB
    std::memcpy(out, pos_, count * sizeof(T));
    pos_ += count * sizeof(T);
  }
  const char* advance(std::uint64_t bytes) {
    const char* start = pos_;
    pos_ += bytes;
    return start;
  }
  void seek(const char* at) { pos_ = at; }

  // --- errors -----------------------------------------------------------------------------------
  SourceLocation locate(const char* at) const;
  [[noreturn]] void failAt(const char* at, const std::string& message) const;
  [[noreturn]] void fail(const std::string& message) const { failAt(pos_, message); }
  // Error for the whole file (no position): "file: error: message".
  [[noreturn]] void failFile(const std::string& message) const;

 private:
  bool endsToken(const char* next) const { return next > pos_ && (next == end_ || isTextSpace(*next)); }
  [[noreturn]] void failNumber(const char* what, bool outOfRange, const char* kind = "an integer") const;
  [[noreturn]] void failTooFew(std::uint64_t count, std::uint64_t itemBytes, const char* what) const;

  const char* begin_;
  const char* pos_;
  const char* end_;
  std::string file_;
  bool binaryLocations_ = false;
};

}  // namespace lancer
