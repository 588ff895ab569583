#include "piped_output.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

#include "lancer/util/input_error.hpp"

namespace lancer::cli {

PipedOutput::PipedOutput() {
  if (isatty(STDOUT_FILENO))
    throw InputError(
        SourceLocation{"-o"},
        "-o - writes the PNG to stdout, which is a terminal: redirect it (-o - > part.png) or pipe "
        "it to a program that reads a PNG");
  const char* folder = std::getenv("TMPDIR");
  std::string name =
      std::string(folder != nullptr && *folder != '\0' ? folder : "/tmp") + "/lancer-XXXXXX.png";
  std::vector<char> buffer(name.begin(), name.end());
  buffer.push_back('\0');
  const int fd = mkstemps(buffer.data(), 4);
  if (fd < 0)
    throw InputError(SourceLocation{"-o"},
                     fmt::format("cannot make a temporary file for -o - in {}: {} (set "
                                 "TMPDIR to a writable folder)",
                                 std::filesystem::path(name).parent_path().string(), std::strerror(errno)));
  close(fd);
  path_ = buffer.data();
}

PipedOutput::~PipedOutput() {
  if (!path_.empty()) std::remove(path_.c_str());
}

void PipedOutput::send() const {
  // A reader that stops early (`| head -c 100`) makes the write fail with EPIPE instead of killing
  // lancer, so that the temporary file is still removed.
  std::signal(SIGPIPE, SIG_IGN);
  std::FILE* in = std::fopen(path_.c_str(), "rb");
  if (in == nullptr)
    throw InputError(SourceLocation{path_},
                     fmt::format("cannot read the picture back: {}", std::strerror(errno)));
  std::vector<char> chunk(1 << 16);
  bool failed = false;
  std::size_t got = 0;
  while (!failed && (got = std::fread(chunk.data(), 1, chunk.size(), in)) > 0)
    failed = std::fwrite(chunk.data(), 1, got, stdout) != got;
  std::fclose(in);
  if (failed || std::fflush(stdout) != 0)
    throw InputError(SourceLocation{"stdout"},
                     fmt::format("cannot write the picture to stdout: {}", std::strerror(errno)));
}

std::string outputNamedAfter(const std::string& input, const std::string& extension) {
  std::string stem = std::filesystem::path(input).stem().string();
  // A step pattern: its name without the wildcards and the separators before them.
  std::erase_if(stem, [](char c) { return c == '*' || c == '?' || c == '[' || c == ']'; });
  while (!stem.empty() && (stem.back() == '_' || stem.back() == '-' || stem.back() == '.')) stem.pop_back();
  if (stem.empty()) stem = "lancer";
  return stem + extension;
}

}  // namespace lancer::cli
