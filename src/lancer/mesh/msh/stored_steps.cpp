#include "lancer/mesh/msh/stored_steps.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "lancer/mesh/msh/fields.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

class OpenFile {
 public:
  explicit OpenFile(const std::string& path) : fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {}
  ~OpenFile() {
    if (fd_ >= 0) ::close(fd_);
  }
  OpenFile(const OpenFile&) = delete;
  OpenFile& operator=(const OpenFile&) = delete;
  int fd() const { return fd_; }

 private:
  int fd_;
};

[[noreturn]] void failRead(const std::string& path, const std::string& why) {
  throw InputError(SourceLocation{path},
                   fmt::format("cannot read the result steps again: {} (lancer reads the steps of a large "
                               "result from the file when a frame needs them; keep the file in place and "
                               "unchanged while lancer runs)",
                               why));
}

}  // namespace

std::shared_ptr<const std::vector<float>> StoredFieldSteps::load(std::size_t index) const {
  const std::lock_guard lock(mutex_);
  for (const auto& [section, values] : recent_)
    if (section == index) return values;
  const MshFieldSection& section = sections_.at(index);
  const OpenFile file(path_);
  if (file.fd() < 0) failRead(path_, std::strerror(errno));
  struct stat info {};
  if (::fstat(file.fd(), &info) != 0) failRead(path_, std::strerror(errno));
  const FileIdentity now{static_cast<std::uint64_t>(info.st_size), info.st_mtim.tv_sec, info.st_mtim.tv_nsec};
  if (!(now == identity_)) failRead(path_, "the file changed since it was read");
  std::vector<char> bytes(section.recordsEnd - section.recordsBegin);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t got = ::pread(file.fd(), bytes.data() + done, bytes.size() - done,
                                static_cast<off_t>(section.recordsBegin + done));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) failRead(path_, got < 0 ? std::strerror(errno) : "the file is shorter than it was");
    done += static_cast<std::size_t>(got);
  }
  MshCursor cursor(bytes, path_);
  cursor.setBinaryLocations(true);     // offsets in the records, should the bytes no longer parse
  MshFieldSection inBuffer = section;  // the records' offsets in `bytes`
  inBuffer.recordsBegin = 0;
  inBuffer.recordsEnd = bytes.size();
  std::vector<std::string> warnings;  // said when the file was first read
  MeshField field = readMshFieldRecords(cursor, inBuffer, *mapping_, warnings);
  auto values = std::make_shared<const std::vector<float>>(std::move(field.values));
  ++fileReads_;
  // Two steps of every view: a blend of two steps, of each view a picture uses (colour and warp).
  if (recent_.size() >= 2 * views_) recent_.erase(recent_.begin());
  recent_.emplace_back(index, values);
  return values;
}

void StoredFieldSteps::forgetKept() const {
  const std::lock_guard lock(mutex_);
  recent_.clear();
}

std::size_t StoredFieldSteps::countViews(const std::vector<MshFieldSection>& sections) {
  std::vector<std::string> names;
  for (const MshFieldSection& section : sections)
    if (std::find(names.begin(), names.end(), section.field.name) == names.end())
      names.push_back(section.field.name);
  return std::max<std::size_t>(names.size(), 1);
}

std::size_t StoredFieldSteps::fileReads() const {
  const std::lock_guard lock(mutex_);
  return fileReads_;
}

}  // namespace lancer
