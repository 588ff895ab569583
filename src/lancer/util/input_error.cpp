#include "lancer/util/input_error.hpp"

#include <fmt/format.h>

namespace lancer {

namespace {

std::string formatLocated(const SourceLocation& location, const char* severity, const std::string& message) {
  std::string where = location.file.empty() ? std::string("<input>") : location.file;
  if (location.byteOffset >= 0) {
    where += fmt::format(":@{}", location.byteOffset);
  } else if (location.line > 0) {
    where += fmt::format(":{}", location.line);
    if (location.column > 0) where += fmt::format(":{}", location.column);
  }
  return fmt::format("{}: {}: {}", where, severity, message);
}

}  // namespace

std::string formatInputError(const SourceLocation& location, const std::string& message) {
  return formatLocated(location, "error", message);
}

std::string formatInputWarning(const SourceLocation& location, const std::string& message) {
  return formatLocated(location, "warning", message);
}

InputError::InputError(SourceLocation location, const std::string& message)
    : std::runtime_error(formatInputError(location, message)),
      location_(std::move(location)),
      message_(message) {}

InputError::InputError(const std::string& file, std::int64_t line, const std::string& message)
    : InputError(SourceLocation{file, line, 0, -1}, message) {}

}  // namespace lancer
