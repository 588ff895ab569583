#include "lancer/mesh/pos/pos_split.hpp"

#include <cstring>
#include <string_view>

#include "lancer/mesh/pos/pos_element_kinds.hpp"

namespace lancer {
namespace {

bool isCodeChar(char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); }

// The first line start at or after `from` and before `to` whose line begins (after blanks) with an
// element code and '(', or nullptr.
const char* elementLineStart(const char* from, const char* to, const char* end) {
  for (const char* p = from; p < to;) {
    const void* newline = std::memchr(p, '\n', static_cast<std::size_t>(to - p));
    if (!newline) return nullptr;
    const char* q = static_cast<const char*>(newline) + 1;
    p = q;
    while (q < end && (*q == ' ' || *q == '\t' || *q == '\r')) ++q;
    const char* code = q;
    while (q < end && q - code < 4 && isCodeChar(*q)) ++q;
    if (q < end && *q == '(' && posElementKind(std::string_view(code, static_cast<std::size_t>(q - code))))
      return code;
  }
  return nullptr;
}

}  // namespace

std::vector<const char*> posPieceStarts(std::span<const char> bytes, std::size_t pieces) {
  std::vector<const char*> starts;
  const char* begin = bytes.data();
  const char* end = begin + bytes.size();
  for (std::size_t i = 1; i < pieces; ++i) {
    const char* from = begin + bytes.size() * i / pieces;
    const char* to = begin + bytes.size() * (i + 1) / pieces;
    if (!starts.empty() && from <= starts.back()) from = starts.back() + 1;
    if (const char* start = elementLineStart(from, to, end)) starts.push_back(start);
  }
  return starts;
}

}  // namespace lancer
