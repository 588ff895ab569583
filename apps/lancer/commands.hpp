// The subcommands of the lancer CLI. Each registers its options on the CLI11 app and sets the
// runner that main() calls after parsing; runners return the process exit code.
// Map: docs/architecture.md (the path of a ray through the modules).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace lancer::cli {

using CommandRunner = std::function<int()>;

// Exit codes, documented in the README and in `lancer --help`.
inline constexpr int kExitOk = 0;
inline constexpr int kExitInternalError = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitInterrupted = 130;  // Ctrl-C: 128 + SIGINT, as shells report it

void addInfoCommand(CLI::App& app, CommandRunner& runner);
void addRenderCommand(CLI::App& app, CommandRunner& runner);
void addAnimateCommand(CLI::App& app, CommandRunner& runner);
void addAssembleCommand(CLI::App& app, CommandRunner& runner);
void addProbeCommand(CLI::App& app, CommandRunner& runner);

}  // namespace lancer::cli
