// "Did you mean ...?" for misspelt names in scene files: the closest known name by edit distance,
// offered only when it is close enough to be a likely typo.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace lancer {

// Optimal string alignment distance (Levenshtein plus adjacent transpositions), ASCII case-insensitive.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidate closest to `word` when the distance is small for its length (1 for short names,
// 2 from five characters, 3 from nine); ties go to the earlier candidate.
std::optional<std::string> closestName(std::string_view word, std::span<const std::string_view> candidates);
std::optional<std::string> closestName(std::string_view word, std::span<const std::string> candidates);

// The command-line option `given` most likely stands for: the closest of `options` (spelt with their
// dashes, "--width", "-o") to its name, the part before any '=' ("--widht=80" -> "--width"), or nothing.
std::optional<std::string> closestOption(std::string_view given, std::span<const std::string> options);

// " (did you mean 'shininess'?)", or "" when nothing is close.
std::string didYouMean(std::string_view word, std::span<const std::string_view> candidates);
std::string didYouMean(std::string_view word, std::span<const std::string> candidates);

}  // namespace lancer
