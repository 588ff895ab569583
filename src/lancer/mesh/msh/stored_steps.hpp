// The field steps of one .msh file that were left in the file (mesh/mesh_field.hpp: stored steps),
// read back on demand. The reader read each one once already (checked, ranged), so reading it
// again cannot fail on its content; the file is checked to be the one read (size, modification
// time) before every read. The last two steps of each view read stay in memory: an animation's
// frame shows one or two steps (a blend) of each view it uses, often under several uses (colour and
// warp by the same view).
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "lancer/mesh/msh/field_mapping.hpp"

namespace lancer {

// What identifies the bytes a file had when it was read.
struct FileIdentity {
  std::uint64_t bytes = 0;
  std::int64_t modifiedSeconds = 0;
  std::int64_t modifiedNanoseconds = 0;
  friend bool operator==(const FileIdentity&, const FileIdentity&) = default;
};

class StoredFieldSteps {
 public:
  StoredFieldSteps(std::string path, FileIdentity identity, std::shared_ptr<const MshFieldMapping> mapping,
                   std::vector<MshFieldSection> sections)
      : path_(std::move(path)),
        identity_(identity),
        mapping_(std::move(mapping)),
        sections_(std::move(sections)),
        views_(countViews(sections_)) {}

  const std::string& path() const { return path_; }
  // Section `index`'s values in mesh order. Safe to call from several threads.
  std::shared_ptr<const std::vector<float>> load(std::size_t index) const;
  // Drops the steps kept (before a large allocation, such as a tree's build: they are read again
  // when needed).
  void forgetKept() const;
  // How many times a section was read from the file (not from the two kept), for tests and bench.
  std::size_t fileReads() const;

 private:
  std::string path_;
  FileIdentity identity_;
  std::shared_ptr<const MshFieldMapping> mapping_;
  static std::size_t countViews(const std::vector<MshFieldSection>& sections);

  std::vector<MshFieldSection> sections_;
  std::size_t views_;  // distinct view names
  mutable std::mutex mutex_;
  mutable std::vector<std::pair<std::size_t, std::shared_ptr<std::vector<float>>>> recent_;
  mutable std::size_t fileReads_ = 0;
};

}  // namespace lancer
