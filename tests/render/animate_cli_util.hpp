// Helpers for the `lancer animate` tests: running the built CLI, the committed turntable scene, and
// reading numbered frames back as the 8-bit values the writers stored.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <string>
#include <vector>

#include "lancer/image/image_io.hpp"

namespace lancer::test {

inline const std::string kTurntableScene = std::string(LANCER_TEST_DATA_DIR) + "/render/turntable.toml";

struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

// Runs a shell command, capturing stdout and stderr together.
inline CommandResult runShell(const std::string& command) {
  CommandResult result;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  std::size_t got;
  while ((got = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, got);
  const int status = ::pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// Runs `lancer ARGUMENTS` (arguments already quoted for the shell), optionally under a prefix such as
// "timeout -s INT 1".
inline CommandResult runCli(const std::string& arguments, const std::string& prefix = "") {
  return runShell(prefix + " '" + LANCER_CLI_PATH + "' " + arguments);
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

inline std::string quoted(const std::string& path) { return "'" + path + "'"; }

// A PNG frame as interleaved 8-bit RGB: exactly what lancer stored (linear curve, no alpha).
inline std::vector<std::uint8_t> pngRgb8(const std::string& path) {
  return encodeImage8(readPng(path), TransferCurve::Linear, 3);
}

}  // namespace lancer::test
