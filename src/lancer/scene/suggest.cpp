#include "lancer/scene/suggest.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

#include <fmt/format.h>

namespace lancer {
namespace {

char lowerAscii(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

std::size_t allowedDistance(std::string_view word) {
  if (word.size() >= 9) return 3;
  if (word.size() >= 5) return 2;
  return 1;
}

template <typename String>
std::optional<std::string> closestNameIn(std::string_view word, std::span<const String> candidates) {
  std::optional<std::string> best;
  std::size_t bestDistance = allowedDistance(word) + 1;
  for (const String& candidate : candidates) {
    const std::string_view name(candidate);
    const std::size_t distance = editDistance(word, name);
    // A one-letter candidate is "close" to every one-letter word; demand more than replacing it whole.
    if (distance < bestDistance && distance < std::max(word.size(), name.size())) {
      best = std::string(name);
      bestDistance = distance;
    }
  }
  return best;
}

template <typename String>
std::string didYouMeanIn(std::string_view word, std::span<const String> candidates) {
  const std::optional<std::string> best = closestNameIn(word, candidates);
  return best ? fmt::format(" (did you mean '{}'?)", *best) : std::string();
}

}  // namespace

// Wagner-Fischer with the transposition case of Damerau; names here are short, two rows would do,
// three keep the transposition readable.
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> previous2(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = lowerAscii(a[i - 1]) == lowerAscii(b[j - 1]);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (same ? 0 : 1)});
      if (i > 1 && j > 1 && lowerAscii(a[i - 1]) == lowerAscii(b[j - 2]) &&
          lowerAscii(a[i - 2]) == lowerAscii(b[j - 1]))
        current[j] = std::min(current[j], previous2[j - 2] + 1);
    }
    std::swap(previous2, previous);
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::optional<std::string> closestName(std::string_view word, std::span<const std::string_view> candidates) {
  return closestNameIn(word, candidates);
}
std::optional<std::string> closestName(std::string_view word, std::span<const std::string> candidates) {
  return closestNameIn(word, candidates);
}
std::optional<std::string> closestOption(std::string_view given, std::span<const std::string> options) {
  const std::string_view name = given.substr(0, given.find('='));
  // "--" and "-" alone say nothing; the dashes count as letters, so "-width" finds "--width".
  if (name.find_first_not_of('-') == std::string_view::npos) return std::nullopt;
  return closestNameIn(name, options);
}

std::string didYouMean(std::string_view word, std::span<const std::string_view> candidates) {
  return didYouMeanIn(word, candidates);
}
std::string didYouMean(std::string_view word, std::span<const std::string> candidates) {
  return didYouMeanIn(word, candidates);
}

}  // namespace lancer
