#include "lancer/image/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

std::string folderOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

std::string baseNameOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The process umask without changing it (umask() would race with other threads): Linux >= 4.7
// reports it in /proc/self/status.
mode_t currentUmask() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("Umask:", 0) == 0) {
      const unsigned long mask = std::strtoul(line.c_str() + 6, nullptr, 8);
      return static_cast<mode_t>(mask & 0777);
    }
  }
  return 022;
}

// Why a write failed, in words a user can act on.
std::string writeFailureReason(int errorNumber) {
  switch (errorNumber) {
    case ENOSPC:
      return "no space left on the device";
    case EDQUOT:
      return "disk quota exceeded";
    case EFBIG:
      return "the file would exceed the file size limit (see 'ulimit -f')";
    default:
      return std::strerror(errorNumber);
  }
}

std::string createFailureReason(int errorNumber, const std::string& folder) {
  switch (errorNumber) {
    case ENOENT:
      return fmt::format("the folder '{}' does not exist", folder);
    case ENOTDIR:
      return fmt::format("'{}' is not a folder", folder);
    case EACCES:
    case EPERM:
      return fmt::format("no permission to create files in the folder '{}'", folder);
    case EROFS:
      return fmt::format("the folder '{}' is on a read-only file system", folder);
    default:
      return fmt::format("cannot create a file in the folder '{}': {}", folder,
                         writeFailureReason(errorNumber));
  }
}

// Temporary paths for removePendingTemporaryFiles(), which may run in a signal handler: fixed
// buffers, published by an atomic state (0 free, 1 being filled, 2 holds a live temporary path).
constexpr int kSignalSlots = 64;
struct SignalSlot {
  std::atomic<int> state{0};
  char path[4096] = {};
};
SignalSlot gSignalSlots[kSignalSlots];

int claimSignalSlot(const std::string& path) {
  if (path.size() >= sizeof(SignalSlot::path)) return -1;
  for (int i = 0; i < kSignalSlots; ++i) {
    int expected = 0;
    if (gSignalSlots[i].state.compare_exchange_strong(expected, 1)) {
      std::memcpy(gSignalSlots[i].path, path.c_str(), path.size() + 1);
      gSignalSlots[i].state.store(2);
      return i;
    }
  }
  return -1;  // too many writers at once: this one is not cleaned up on a signal
}

void releaseSignalSlot(int& slot) {
  if (slot >= 0) gSignalSlots[slot].state.store(0);
  slot = -1;
}

}  // namespace

void removePendingTemporaryFiles() noexcept {
  for (SignalSlot& slot : gSignalSlots) {
    if (slot.state.load() == 2) ::unlink(slot.path);
  }
}

AtomicFileWriter::AtomicFileWriter(std::string targetPath) : targetPath_(std::move(targetPath)) {
  const std::string folder = folderOf(targetPath_);
  std::string name = baseNameOf(targetPath_);
  if (name.empty() || name == "." || name == "..") {
    throw InputError(SourceLocation{targetPath_},
                     "cannot write here: the output path names a folder, not a file");
  }
  struct stat targetStat {};
  mode_t mode = 0666 & ~currentUmask();
  if (::stat(targetPath_.c_str(), &targetStat) == 0) {
    if (S_ISDIR(targetStat.st_mode)) {
      throw InputError(SourceLocation{targetPath_}, "cannot write here: this is a folder, not a file");
    }
    targetExisted_ = true;
    mode = targetStat.st_mode & 07777;
  }
  // Keep the temporary name under NAME_MAX (255) even for long target names.
  if (name.size() > 200) name.resize(200);
  tempPath_ = (folder == "/" ? std::string("/") : folder + "/") + "." + name + ".tmp-XXXXXX";
  std::vector<char> pattern(tempPath_.begin(), tempPath_.end());
  pattern.push_back('\0');
  const int fd = ::mkostemp(pattern.data(), O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    tempPath_.clear();
    throw InputError(SourceLocation{targetPath_}, "cannot write here: " + createFailureReason(error, folder));
  }
  tempPath_.assign(pattern.data());
  signalSlot_ = claimSignalSlot(tempPath_);
  ::fchmod(fd, mode);  // best effort: mkstemp makes 0600, which would surprise the user
  stream_ = ::fdopen(fd, "wb");
  if (stream_ == nullptr) {
    const int error = errno;
    ::close(fd);
    ::unlink(tempPath_.c_str());
    releaseSignalSlot(signalSlot_);
    tempPath_.clear();
    throw InputError(SourceLocation{targetPath_}, fmt::format("cannot write here: {}", std::strerror(error)));
  }
  static_cast<void>(std::setvbuf(stream_, nullptr, _IOFBF, 1 << 16));
}

AtomicFileWriter::~AtomicFileWriter() { discard(); }

void requireWritable(const std::string& path) {
  AtomicFileWriter probe(path);  // its temporary file is removed when it goes
}

bool sameOutputPath(const std::string& a, const std::string& b) {
  std::error_code errorA, errorB;
  const std::filesystem::path first = std::filesystem::weakly_canonical(a, errorA);
  const std::filesystem::path second = std::filesystem::weakly_canonical(b, errorB);
  if (!errorA && !errorB) return first == second;
  return std::filesystem::absolute(a, errorA).lexically_normal() ==
         std::filesystem::absolute(b, errorB).lexically_normal();
}

bool AtomicFileWriter::write(const void* data, std::size_t size) noexcept {
  if (errorNumber_ != 0 || stream_ == nullptr) return false;
  if (size == 0) return true;
  errno = 0;
  if (std::fwrite(data, 1, size, stream_) != size) {
    errorNumber_ = errno != 0 ? errno : EIO;
    return false;
  }
  return true;
}

bool AtomicFileWriter::writeAt(std::uint64_t offset, const void* data, std::size_t size) noexcept {
  if (errorNumber_ != 0 || stream_ == nullptr) return false;
  errno = 0;
  if (offset > static_cast<std::uint64_t>(std::numeric_limits<off_t>::max()) ||
      ::fseeko(stream_, static_cast<off_t>(offset), SEEK_SET) != 0) {
    errorNumber_ = errno != 0 ? errno : EIO;
    return false;
  }
  return write(data, size);
}

void AtomicFileWriter::throwIfFailed() {
  if (errorNumber_ != 0) failAndThrow("writing", errorNumber_);
}

void AtomicFileWriter::discard() noexcept {
  if (stream_ != nullptr) {
    std::fclose(stream_);
    stream_ = nullptr;
  }
  if (!tempPath_.empty()) {
    ::unlink(tempPath_.c_str());
    tempPath_.clear();
  }
  releaseSignalSlot(signalSlot_);
}

void AtomicFileWriter::failAndThrow(const std::string& what, int errorNumber) {
  discard();
  const std::string outcome = targetExisted_ ? "the existing file was left unchanged" : "no file was written";
  throw InputError(SourceLocation{targetPath_},
                   fmt::format("{} failed: {}; {}", what, writeFailureReason(errorNumber), outcome));
}

void AtomicFileWriter::commit() {
  if (stream_ == nullptr) {
    throw InputError(SourceLocation{targetPath_}, "writing failed: the file was already closed");
  }
  if (errorNumber_ != 0) failAndThrow("writing", errorNumber_);
  errno = 0;
  if (std::fflush(stream_) != 0) failAndThrow("writing", errno != 0 ? errno : EIO);
  if (::fsync(::fileno(stream_)) != 0 && errno != EINVAL) failAndThrow("writing", errno);
  const int closeResult = std::fclose(stream_);
  stream_ = nullptr;
  if (closeResult != 0) failAndThrow("writing", errno != 0 ? errno : EIO);
  if (::rename(tempPath_.c_str(), targetPath_.c_str()) != 0) failAndThrow("replacing the file", errno);
  tempPath_.clear();
  releaseSignalSlot(signalSlot_);  // after the rename: a signal in between unlinks nothing that exists
  // Make the rename itself durable; a failure here loses nothing already visible, so it is ignored.
  const int folderFd = ::open(folderOf(targetPath_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (folderFd >= 0) {
    ::fsync(folderFd);
    ::close(folderFd);
  }
}

void writeFileAtomically(const std::string& path, std::span<const std::uint8_t> bytes) {
  AtomicFileWriter file(path);
  file.write(bytes);
  file.commit();
}

}  // namespace lancer
