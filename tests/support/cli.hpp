// Running shell commands and the built `lancer` CLI from tests, as a user's shell would, and finding
// the optional tools (Pillow, ImageMagick) that some tests decode our files with.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace lancer::test {

struct CommandResult {
  int exitCode = -1;  // -1 when the command could not start or did not exit normally
  std::string output;
};

// Runs `command` with /bin/sh; the output is what it wrote to stdout (end the command with
// " 2>&1" to capture stderr too).
CommandResult runShell(const std::string& command);

// Runs `lancer ARGUMENTS` (arguments already quoted for the shell), stdout and stderr together,
// optionally under a prefix such as "timeout -s INT 1".
CommandResult runCli(const std::string& arguments, const std::string& prefix = "");

// `path` in single quotes, for a command line.
std::string quoted(const std::string& path);

bool contains(const std::string& text, const std::string& part);

// Adds a gtest failure for each of `parts` that `text` does not contain, with the whole text: the
// check of a report that must show these lines, in any order.
void expectContainsAll(const std::string& text, std::initializer_list<std::string_view> parts);

// The first python3 that has Pillow: the one on PATH, else the system's (Debian's python3-pil).
std::optional<std::string> pythonWithPillow();

// Whether ImageMagick's `identify` runs.
bool imageMagickInstalled();

}  // namespace lancer::test
