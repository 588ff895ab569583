#include "lancer/mesh/msh/cursor.hpp"

#include "lancer/util/memory_budget.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace lancer {

SourceLocation MshCursor::locate(const char* at) const {
  at = std::clamp(at, begin_, end_);
  SourceLocation location{file_};
  if (binaryLocations_) {
    location.byteOffset = at - begin_;
    return location;
  }
  // Lines are counted only when an error is reported, so the parser never tracks them.
  location.line = 1 + std::count(begin_, at, '\n');
  const char* lineStart = at;
  while (lineStart > begin_ && lineStart[-1] != '\n') --lineStart;
  location.column = 1 + (at - lineStart);
  return location;
}

void MshCursor::failAt(const char* at, const std::string& message) const {
  throw InputError(locate(at), message);
}

void MshCursor::failFile(const std::string& message) const {
  throw InputError(SourceLocation{file_}, message);
}

void MshCursor::expectToken(std::string_view expected, const char* context) {
  skipWhitespace();
  const char* start = pos_;
  const std::string_view found = token();
  if (found == expected) return;
  if (found.empty())
    failAt(start, fmt::format("expected {} {}, found the end of the file (the file looks truncated)",
                              expected, context));
  failAt(start, fmt::format("expected {} {}, found {}", expected, context, quoteTokenForMessage(found)));
}

void MshCursor::failNumber(const char* what, bool outOfRange, const char* kind) const {
  MshCursor copy = *this;
  copy.skipWhitespace();
  const char* start = copy.pos_;
  const std::string_view found = copy.token();
  if (found.empty())
    failAt(start,
           fmt::format("expected {} ({}), found the end of the file (the file looks truncated)", what, kind));
  if (outOfRange) failAt(start, fmt::format("{} {} is out of range", what, quoteTokenForMessage(found)));
  failAt(start, fmt::format("expected {} ({}), found {}", what, kind, quoteTokenForMessage(found)));
}

void MshCursor::requireMemory(std::uint64_t count, const char* what) const {
  const std::uint64_t bytes = saturatingProduct(count, kMeshBytesPerItem);
  // The location counts the lines before it: only for the message.
  if (bytes <= memoryBudget()) return;
  lancer::requireMemory(bytes, locate(pos_), fmt::format("{} with {} entries", what, count));
}

void MshCursor::failTooFew(std::uint64_t count, std::uint64_t itemBytes, const char* what) const {
  if (count == 1)
    fail(fmt::format("{} needs {} bytes, but only {} remain (the file looks truncated)", what, itemBytes,
                     remaining()));
  fail(
      fmt::format("{} declares {} entries of at least {} bytes each, but only {} bytes remain in the file "
                  "(truncated file or a corrupt count)",
                  what, count, itemBytes, remaining()));
}

}  // namespace lancer
