// A read-only memory mapping of a whole input file (a mesh, a post-processing view): the readers parse
// straight from the mapped bytes. Errors name the file and the kind of file the reader expected.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace lancer {

class MappedFile {
 public:
  // kind: what the file should be, for messages: "folder.msh: error: is a directory, not a .msh file".
  // Throws InputError when the file cannot be opened, stated or mapped, or is not a regular file.
  MappedFile(const std::string& path, std::string_view kind);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::span<const char> bytes() const { return {data_, size_}; }
  // The modification time the file had when it was mapped (readers that read it again compare it).
  std::int64_t modifiedSeconds() const { return modifiedSeconds_; }
  std::int64_t modifiedNanoseconds() const { return modifiedNanoseconds_; }

 private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
  std::int64_t modifiedSeconds_ = 0;
  std::int64_t modifiedNanoseconds_ = 0;
};

}  // namespace lancer
