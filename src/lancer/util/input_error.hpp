// Errors caused by the user's input (mesh files, scene files, command-line values).
// They carry the location in the user's file, are thrown by the library and printed once by the CLI.
// Map: docs/architecture.md (the path of a ray through the modules).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace lancer {

// A location in a user's file: a line (and optional column) for text, a byte offset for binary.
struct SourceLocation {
  std::string file;
  std::int64_t line = 0;         // 1-based; 0 when unknown or not a text position
  std::int64_t column = 0;       // 1-based; 0 when unknown
  std::int64_t byteOffset = -1;  // >= 0 for binary files, where lines mean nothing
};

// Thrown for bad input. what() is the full compiler-style line:
//   "part.msh:1042:7: error: element 17 uses node 9001, but $Nodes declares 9000"
class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation location, const std::string& message);
  InputError(const std::string& file, std::int64_t line, const std::string& message);

  const SourceLocation& location() const { return location_; }
  const std::string& message() const { return message_; }

 private:
  SourceLocation location_;
  std::string message_;
};

// "file:line:col: error: message" (parts that are unknown are left out; binary: "file:@offset").
std::string formatInputError(const SourceLocation& location, const std::string& message);
// The same with "warning:", for input lancer accepts but the user should hear about.
std::string formatInputWarning(const SourceLocation& location, const std::string& message);

}  // namespace lancer
