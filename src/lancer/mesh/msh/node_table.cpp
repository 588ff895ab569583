#include "lancer/mesh/msh/node_table.hpp"

#include <algorithm>

#include "lancer/util/huge_pages.hpp"

namespace lancer {

void MshNodeTable::reserve(std::size_t count) {
  tags_.reserve(count);
  coords_.reserve(count);
  adviseHugePages(tags_);
  adviseHugePages(coords_);
}

std::optional<std::uint64_t> MshNodeTable::buildLookup() {
  contiguous_ = false;
  denseIndex_.clear();
  sparseIndex_.clear();
  lookupCount_ = tags_.size();
  if (tags_.empty()) return std::nullopt;
  const auto [minIt, maxIt] = std::minmax_element(tags_.begin(), tags_.end());
  minTag_ = *minIt;
  const std::uint64_t span = *maxIt - *minIt;
  contiguous_ = span + 1 == tags_.size();
  for (std::size_t i = 0; contiguous_ && i < tags_.size(); ++i) contiguous_ = tags_[i] == minTag_ + i;
  if (contiguous_) return std::nullopt;  // no duplicates possible: every tag of the range occurs once
  // A direct table while the tags are reasonably dense (4 bytes per possible tag, bounded by the
  // node count); otherwise a sorted table and binary search.
  dense_ = span < 4 * static_cast<std::uint64_t>(tags_.size()) + 1024;
  if (dense_) {
    denseIndex_.assign(span + 1, kNoVertex);
    for (std::size_t i = 0; i < tags_.size(); ++i) {
      std::uint32_t& slot = denseIndex_[tags_[i] - minTag_];
      if (slot != kNoVertex) return tags_[i];
      slot = static_cast<std::uint32_t>(i);
    }
    return std::nullopt;
  }
  sparseIndex_.resize(tags_.size());
  for (std::size_t i = 0; i < tags_.size(); ++i) sparseIndex_[i] = {tags_[i], static_cast<std::uint32_t>(i)};
  std::sort(sparseIndex_.begin(), sparseIndex_.end());
  for (std::size_t i = 1; i < sparseIndex_.size(); ++i) {
    if (sparseIndex_[i].first == sparseIndex_[i - 1].first) return sparseIndex_[i].first;
  }
  return std::nullopt;
}

std::uint32_t MshNodeTable::findSparse(std::uint64_t tag) const {
  const auto it =
      std::lower_bound(sparseIndex_.begin(), sparseIndex_.end(), std::make_pair(tag, std::uint32_t{0}));
  return (it != sparseIndex_.end() && it->first == tag) ? it->second : kNoVertex;
}

}  // namespace lancer
