// lancer: command-line entry point. Subcommands live in their own files; this one parses the
// command line, runs the chosen subcommand and turns exceptions into one-line messages and exit codes.
#include <malloc.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "lancer/cluster/mpi_distribution.hpp"
#include "lancer/scene/suggest.hpp"
#include "lancer/util/input_error.hpp"
#include "lancer/util/memory_budget.hpp"
#include "scene_setup.hpp"

namespace {

// The first word of the command line when it names no subcommand (`lancer view x`), else "".
std::string unknownSubcommand(CLI::App& app, int argc, char** argv) {
  if (!app.get_subcommands().empty()) return {};
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word == "--max-memory") {
      ++i;  // the global option's value
      continue;
    }
    if (word.empty() || word[0] == '-') continue;
    for (const CLI::App* command : app.get_subcommands({}))
      if (command->check_name(word)) return {};
    return word;
  }
  return {};
}

// The options a command takes, as typed: "--width", "-o"; with the global ones (--max-memory, -V, ...).
std::vector<std::string> optionNames(const CLI::App& command, const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* owner : {&command, &app}) {
    for (const CLI::Option* option : owner->get_options()) {
      for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
      for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    }
    if (owner == &app) break;
  }
  return names;
}

// "lancer: error: unknown option '--widht' (did you mean '--width'?); ..." for the first word of the
// command line that looks like an option and is none of the command's; "" when there is none (an
// extra positional value: CLI11's own message says so).
std::string unknownOptionMessage(CLI::App& app, int argc, char** argv) {
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  const CLI::App& command = chosen.empty() ? app : *chosen.front();
  // Without a subcommand CLI11 stops at the missing subcommand: the words are all there is.
  std::vector<std::string> words = app.remaining(true);
  if (chosen.empty())
    for (int i = 1; i < argc; ++i) {
      const std::string word = argv[i];
      if (word == "--max-memory") ++i;  // and its value
      const std::string name = word.substr(0, word.find('='));
      if (name.size() > 1 && name[0] == '-' && app.get_option_no_throw(name) == nullptr)
        words.push_back(word);
    }
  for (const std::string& word : words) {
    if (word.size() < 2 || word[0] != '-') continue;
    char* end = nullptr;
    std::strtod(word.c_str(), &end);
    if (end == word.c_str() + word.size()) continue;  // a negative number, a value
    const std::vector<std::string> names = optionNames(command, app);
    const std::optional<std::string> closest = lancer::closestOption(word, names);
    const std::string help = chosen.empty() ? "lancer --help" : "lancer " + command.get_name() + " --help";
    return "lancer: error: unknown option '" + word.substr(0, word.find('=')) + "'" +
           (closest ? " (did you mean '" + *closest + "'?)" : std::string()) + "; " + help +
           " lists the options";
  }
  return {};
}

}  // namespace

int main(int argc, char** argv) {
  using namespace lancer::cli;
  // A file-size limit (`ulimit -f`) would otherwise kill lancer with SIGXFSZ mid-write, leaving the
  // temporary file behind; ignored, the write fails with EFBIG and the writer reports it cleanly.
  std::signal(SIGXFSZ, SIG_IGN);
  // Buffers of a megabyte and more (a mesh's arrays, a frame's scene and tree) are mapped and unmapped
  // on their own. glibc's default raises that threshold to the size of the largest buffer freed, after
  // which such buffers come from the heap, whose freed middle is never handed back: an animation over
  // warped steps, building a scene per frame, grew by a hundred megabytes of freed memory that way
  // (bench/RESULTS.md, "Animation over 50 warped steps").
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
  setCommandLine(argc, argv);  // what the pictures record as how they were made
  CLI::App app{
      "lancer: a fast ray tracer for gmsh surface meshes.\n"
      "Exit codes: 0 success, 2 bad input (message names the file and line), 1 internal error."};
  app.require_subcommand(1);
  // The positional inputs lead every command's --help under the name of their group.
  app.get_formatter()->label("Positionals", "Input");
  // LANCER_VERSION: CMake's project(VERSION), defined for this file in apps/lancer/CMakeLists.txt.
  app.set_version_flag("-V,--version", "lancer " LANCER_VERSION);
  // Options every subcommand accepts (fallthrough: `lancer render --max-memory 2G x.msh` works too).
  app.fallthrough();
  app.add_option_function<std::string>(
         "--max-memory",
         [](const std::string& text) {
           const auto bytes = lancer::parseByteSize(text);
           if (!bytes)
             throw CLI::ValidationError("--max-memory", "'" + text + "' is not a size like 4G, 512M or 50%");
           lancer::setMemoryBudget(*bytes);
         },
         "Memory budget: inputs that need more fail with a clear message (e.g. 8G, 512M, 50%; "
         "default 75% of physical memory)")
      ->type_name("SIZE");
  CommandRunner runner;
  addInfoCommand(app, runner);
  addRenderCommand(app, runner);
  addAnimateCommand(app, runner);
  addAssembleCommand(app, runner);
  addProbeCommand(app, runner);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (const std::string unknown = unknownSubcommand(app, argc, argv); !unknown.empty()) {
      std::vector<std::string> names;
      std::string commands;
      for (const CLI::App* command : app.get_subcommands({})) {
        names.push_back(command->get_name());
        commands += (commands.empty() ? "" : ", ") + command->get_name();
      }
      std::fprintf(stderr, "lancer: error: unknown subcommand '%s'%s; the commands are %s (lancer --help)\n",
                   unknown.c_str(), lancer::didYouMean(unknown, names).c_str(), commands.c_str());
      return kExitBadInput;
    }
    if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr || app.get_subcommands().empty()) {
      if (const std::string message = unknownOptionMessage(app, argc, argv); !message.empty()) {
        std::fprintf(stderr, "%s\n", message.c_str());
        return kExitBadInput;
      }
    }
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  // In an MPI job a failing rank names itself, and endMpi ends every rank with its exit code.
  const auto rankPrefix = [] {
    const std::string label = lancer::mpiRankLabel();
    return label.empty() ? std::string() : "lancer: " + label + ": ";
  };
  int code = kExitOk;
  try {
    code = runner ? runner() : kExitOk;
  } catch (const lancer::InputError& e) {
    if (interruptRequested()) {
      // A frame or band being committed when Ctrl-C removed its temporary file: the interrupt.
      std::fprintf(stderr, "%slancer: interrupted; the output was not written\n", rankPrefix().c_str());
      code = kExitInterrupted;
    } else {
      std::fprintf(stderr, "%s%s\n", rankPrefix().c_str(), e.what());
      code = kExitBadInput;
    }
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "%slancer: error: out of memory\n", rankPrefix().c_str());
    code = kExitInternalError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%slancer: internal error: %s\n", rankPrefix().c_str(), e.what());
    code = kExitInternalError;
  }
  lancer::endMpi(code);
  return code;
}
