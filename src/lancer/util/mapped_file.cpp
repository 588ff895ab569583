#include "lancer/util/mapped_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "lancer/util/input_error.hpp"

namespace lancer {

MappedFile::MappedFile(const std::string& path, std::string_view kind) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    throw InputError(SourceLocation{path}, fmt::format("cannot open the file: {}", std::strerror(errno)));
  struct stat info {};
  if (::fstat(fd, &info) != 0) {
    const int error = errno;
    ::close(fd);
    throw InputError(SourceLocation{path}, fmt::format("cannot read the file: {}", std::strerror(error)));
  }
  if (S_ISDIR(info.st_mode)) {
    ::close(fd);
    throw InputError(SourceLocation{path}, fmt::format("is a directory, not a {}", kind));
  }
  if (!S_ISREG(info.st_mode)) {
    ::close(fd);
    throw InputError(SourceLocation{path},
                     fmt::format("is not a regular file; lancer memory-maps {}s", kind));
  }
  size_ = static_cast<std::size_t>(info.st_size);
  modifiedSeconds_ = info.st_mtim.tv_sec;
  modifiedNanoseconds_ = info.st_mtim.tv_nsec;
  if (size_ > 0) {
    // No MAP_POPULATE: mapping every page up front measured slower (bench/msh_load_bench.cpp) than
    // letting the sequential parse fault pages in, with the kernel's fault-around.
    void* data = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
    if (data == MAP_FAILED) {
      const int error = errno;
      ::close(fd);
      throw InputError(SourceLocation{path}, fmt::format("cannot map the file: {}", std::strerror(error)));
    }
    data_ = static_cast<const char*>(data);
  }
  ::close(fd);
}

MappedFile::~MappedFile() {
  if (data_) ::munmap(const_cast<char*>(data_), size_);
}

}  // namespace lancer
