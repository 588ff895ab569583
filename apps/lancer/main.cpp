// lancer: command-line entry point. Subcommands live in their own files; this one parses the
// command line, runs the chosen subcommand and turns exceptions into one-line messages and exit codes.
#include <cstdio>
#include <exception>
#include <new>

#include "commands.hpp"
#include "lancer/util/input_error.hpp"

int main(int argc, char** argv) {
  using namespace lancer::cli;
  CLI::App app{
      "lancer: a fast ray tracer for gmsh surface meshes.\n"
      "Exit codes: 0 success, 2 bad input (message names the file and line), 1 internal error."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "lancer 0.1.0");
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
