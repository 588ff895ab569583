// lancer: command-line entry point. Subcommands live in their own files; this one parses the
// command line, runs the chosen subcommand and turns exceptions into one-line messages and exit codes.
#include <csignal>
#include <cstdio>
#include <exception>
#include <new>

#include "commands.hpp"
#include "lancer/util/input_error.hpp"
#include "lancer/util/memory_budget.hpp"

int main(int argc, char** argv) {
  using namespace lancer::cli;
  // A file-size limit (`ulimit -f`) would otherwise kill lancer with SIGXFSZ mid-write, leaving the
  // temporary file behind; ignored, the write fails with EFBIG and the writer reports it cleanly.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{
      "lancer: a fast ray tracer for gmsh surface meshes.\n"
      "Exit codes: 0 success, 2 bad input (message names the file and line), 1 internal error."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "lancer 0.1.0");
  // Options every subcommand accepts (fallthrough: `lancer render --max-memory 2G x.msh` works too).
  app.fallthrough();
  app.add_option_function<std::string>(
         "--max-memory",
         [](const std::string& text) {
           const auto bytes = lancer::parseByteSize(text);
           if (!bytes) throw CLI::ValidationError("--max-memory", "'" + text + "' is not a size like 4G, 512M or 50%");
           lancer::setMemoryBudget(*bytes);
         },
         "Memory budget: inputs that need more fail with a clear message (e.g. 8G, 512M, 50%; "
         "default 75% of physical memory)")
      ->type_name("SIZE");
  CommandRunner runner;
  addInfoCommand(app, runner);
  addRenderCommand(app, runner);
  addAnimateCommand(app, runner);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  try {
    return runner ? runner() : kExitOk;
  } catch (const lancer::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "lancer: error: out of memory\n");
    return kExitInternalError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lancer: internal error: %s\n", e.what());
    return kExitInternalError;
  }
}
