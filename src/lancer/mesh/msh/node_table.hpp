// The nodes of a .msh file while it is read: double coordinates in file order and the lookup from
// gmsh node tag (sparse, unordered, up to 64 bits) to a dense index.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "lancer/math/vec3.hpp"
#include "lancer/mesh/mesh.hpp"

namespace lancer {

class MshNodeTable {
 public:
  void reserve(std::size_t count);
  void add(std::uint64_t tag, const Vec3d& position) {
    tags_.push_back(tag);
    coords_.push_back(position);
  }
  // For bulk binary reads: the caller resizes and fills both arrays.
  std::vector<std::uint64_t>& tags() { return tags_; }
  std::vector<Vec3d>& coords() { return coords_; }
  const std::vector<Vec3d>& coords() const { return coords_; }
  std::size_t size() const { return coords_.size(); }
  std::size_t taggedCount() const { return lookupOnly_ ? lookupCount_ : tags_.size(); }

  // Builds the tag lookup once all nodes are read; returns a tag that occurs twice, if any.
  std::optional<std::uint64_t> buildLookup();

  // Index of the node with this tag, or kNoVertex.
  std::uint32_t find(std::uint64_t tag) const {
    // gmsh numbers nodes 1..N in file order unless told otherwise: then the index is the tag.
    if (contiguous_) {
      const std::uint64_t slot = tag - minTag_;
      return slot < lookupCount_ ? static_cast<std::uint32_t>(slot) : kNoVertex;
    }
    if (dense_) {
      const std::uint64_t slot = tag - minTag_;  // wraps for tag < minTag_, then fails the test
      return slot < denseIndex_.size() ? denseIndex_[slot] : kNoVertex;
    }
    return findSparse(tag);
  }

  // Frees the coordinates, and the tags where the lookup does not need them (gmsh's 1..N), once the
  // mesh has its positions: find() and taggedCount() still work. (`= {}` would keep the capacity.)
  void keepLookupOnly() {
    coords_ = std::vector<Vec3d>();
    lookupOnly_ = true;
    if (contiguous_) tags_ = std::vector<std::uint64_t>();
  }

  // A node made by lancer (the centre of an 8-node quad); it has no tag.
  std::uint32_t addDerived(const Vec3d& position) {
    coords_.push_back(position);
    return static_cast<std::uint32_t>(coords_.size() - 1);
  }

 private:
  std::uint32_t findSparse(std::uint64_t tag) const;

  std::vector<std::uint64_t> tags_;
  std::vector<Vec3d> coords_;
  bool contiguous_ = false;      // tags_[i] == minTag_ + i
  std::size_t lookupCount_ = 0;  // tags_.size() when the lookup was built
  bool lookupOnly_ = false;
  bool dense_ = true;
  std::uint64_t minTag_ = 0;
  std::vector<std::uint32_t> denseIndex_;                             // tag - minTag_ -> index
  std::vector<std::pair<std::uint64_t, std::uint32_t>> sparseIndex_;  // sorted (tag, index)
};

}  // namespace lancer
