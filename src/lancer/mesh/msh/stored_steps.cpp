#include "lancer/mesh/msh/stored_steps.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>

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

void readAt(int fd, const std::string& path, char* buffer, std::size_t bytes, std::uint64_t offset) {
  std::size_t done = 0;
  while (done < bytes) {
    const ssize_t got = ::pread(fd, buffer + done, bytes - done, static_cast<off_t>(offset + done));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) failRead(path, got < 0 ? std::strerror(errno) : "the file is shorter than it was");
    done += static_cast<std::size_t>(got);
  }
}

// A binary $NodeData section's records put straight into mesh order, read a block at a time: the
// general reader wants the whole section in one buffer, 16 MB for a million nodes' displacements,
// paged in afresh for every frame of an animation. Into `values` (its memory reused); false when a
// record is not what the first read found (a tag outside the mesh, a non-finite value), for the
// general reader to say what.
bool readBinaryNodeRecords(int fd, const std::string& path, const MshFieldSection& section,
                           const MshFieldMapping& mapping, std::vector<float>& values) {
  const auto components = static_cast<std::size_t>(section.field.components);
  const std::size_t recordBytes = sizeof(std::int32_t) + components * sizeof(double);
  if (section.recordsEnd - section.recordsBegin != section.count * recordBytes) return false;
  values.assign(mapping.nodeCount * components, std::numeric_limits<float>::quiet_NaN());
  // Blocks under the heap's mmap threshold: their memory is the heap's, not paged in each time.
  constexpr std::size_t kBlockBytes = 256 * 1024;
  const std::size_t blockRecords = std::max<std::size_t>(1, kBlockBytes / recordBytes);
  std::vector<char> block(blockRecords * recordBytes);
  for (std::uint64_t first = 0; first < section.count; first += blockRecords) {
    const std::size_t records = std::min<std::uint64_t>(blockRecords, section.count - first);
    readAt(fd, path, block.data(), records * recordBytes, section.recordsBegin + first * recordBytes);
    const char* at = block.data();
    for (std::size_t r = 0; r < records; ++r) {
      std::int32_t tag;
      std::memcpy(&tag, at, sizeof tag);
      at += sizeof tag;
      const std::uint32_t index = mapping.nodes.find(static_cast<std::uint64_t>(tag));
      if (index == kNoVertex) return false;
      float* out = values.data() + std::size_t{index} * components;
      for (std::size_t c = 0; c < components; ++c, at += sizeof(double)) {
        double value;
        std::memcpy(&value, at, sizeof value);
        if (!std::isfinite(value)) return false;
        out[c] = static_cast<float>(value);
      }
    }
  }
  remapNodeValues(values, section.field.components, mapping.usedNode, mapping.usedCount,
                  mapping.nodes.taggedCount(), mapping.derivedSources);
  return true;
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
  // Two steps of every view are kept: a blend of two steps, of each view a picture uses (colour and
  // warp). The oldest goes first, its memory reused when no one holds it any more.
  std::vector<float> reused;
  if (recent_.size() >= 2 * views_) {
    if (recent_.front().second.use_count() == 1) {
      // No one else holds it: their last release happened before (use_count reads relaxed).
      std::atomic_thread_fence(std::memory_order_acquire);
      reused = std::move(*recent_.front().second);
    }
    recent_.erase(recent_.begin());
  }
  if (!section.binary || section.field.at != FieldAt::kNode ||
      !readBinaryNodeRecords(file.fd(), path_, section, *mapping_, reused)) {
    std::vector<char> bytes(section.recordsEnd - section.recordsBegin);
    readAt(file.fd(), path_, bytes.data(), bytes.size(), section.recordsBegin);
    MshCursor cursor(bytes, path_);
    cursor.setBinaryLocations(true);     // offsets in the records, should the bytes no longer parse
    MshFieldSection inBuffer = section;  // the records' offsets in `bytes`
    inBuffer.recordsBegin = 0;
    inBuffer.recordsEnd = bytes.size();
    std::vector<std::string> warnings;  // said when the file was first read
    reused = readMshFieldRecords(cursor, inBuffer, *mapping_, warnings).values;
  }
  auto values = std::make_shared<std::vector<float>>(std::move(reused));
  ++fileReads_;
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
