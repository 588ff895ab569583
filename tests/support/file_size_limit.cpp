#include "support/file_size_limit.hpp"

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace lancer::test {

std::string underFileSizeLimit(std::uint64_t limitBytes, const std::function<std::string()>& writeFiles) {
  int pipeEnds[2];
  if (::pipe(pipeEnds) != 0) return "(pipe failed)";
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(pipeEnds[0]);
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{static_cast<rlim_t>(limitBytes), static_cast<rlim_t>(limitBytes)};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    const std::string message = writeFiles();
    const ssize_t written = ::write(pipeEnds[1], message.data(), message.size());
    ::_exit(written == static_cast<ssize_t>(message.size()) ? 0 : 1);
  }
  ::close(pipeEnds[1]);
  std::string message;
  char buffer[512];
  ssize_t n;
  while ((n = ::read(pipeEnds[0], buffer, sizeof buffer)) > 0)
    message.append(buffer, static_cast<std::size_t>(n));
  ::close(pipeEnds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return "(child failed: status " + std::to_string(status) + ")";
  return message;
}

}  // namespace lancer::test
