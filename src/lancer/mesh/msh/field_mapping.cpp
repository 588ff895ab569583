#include "lancer/mesh/msh/field_mapping.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lancer/util/huge_pages.hpp"

namespace lancer {

// Keeps the values of the nodes that became mesh vertices, in the same order as the positions.
// The centres lancer adds to 8-node quads (derived nodes, after the file's `tagged` nodes) get the
// serendipity combination of their quad's values, like their positions.
void remapNodeValues(std::vector<float>& values, int componentCount,
                     const std::vector<std::uint8_t>& usedNode, std::uint32_t usedCount, std::size_t tagged,
                     const std::vector<std::array<std::uint32_t, 8>>& derivedSources) {
  const auto components = static_cast<std::size_t>(componentCount);
  values.resize(tagged * components);
  for (const auto& source : derivedSources) {
    for (std::size_t c = 0; c < components; ++c) {
      float value = 0;
      for (int i = 0; i < 4; ++i)
        value += -0.25f * values[source[i] * components + c] + 0.5f * values[source[4 + i] * components + c];
      values.push_back(value);
    }
  }
  // Every node used and every value there (the common case): nothing to move.
  if (usedCount == usedNode.size() && values.size() == usedNode.size() * components) return;
  const std::size_t covered = values.size() / components;
  std::vector<float> kept;
  kept.reserve(std::size_t{usedCount} * components);
  for (std::size_t i = 0; i < usedNode.size(); ++i) {
    if (!usedNode[i]) continue;
    for (std::size_t c = 0; c < components; ++c)
      kept.push_back(i < covered ? values[i * components + c] : std::numeric_limits<float>::quiet_NaN());
  }
  values = std::move(kept);
}

std::vector<float> mapElementValues(std::vector<std::uint64_t> tags, const std::vector<float>& values,
                                    int componentCount, const std::vector<std::uint64_t>& faceElement,
                                    const std::vector<std::pair<std::uint64_t, std::uint64_t>>& aliases,
                                    const MshCoveredElements& covered) {
  for (std::uint64_t& tag : tags) {
    const auto alias = std::lower_bound(aliases.begin(), aliases.end(), std::pair{tag, std::uint64_t{0}});
    if (alias != aliases.end() && alias->first == tag) tag = alias->second;
  }
  // Sorted (tag, record) pairs: one binary search per face.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> byTag(tags.size());
  for (std::size_t r = 0; r < tags.size(); ++r) byTag[r] = {tags[r], static_cast<std::uint32_t>(r)};
  std::sort(byTag.begin(), byTag.end());
  const auto components = static_cast<std::size_t>(componentCount);
  std::vector<float> perFace(faceElement.size() * components, std::numeric_limits<float>::quiet_NaN());
  const auto recordOf = [&](std::uint64_t tag) {
    const auto found = std::lower_bound(byTag.begin(), byTag.end(), std::pair{tag, std::uint32_t{0}});
    return found == byTag.end() || found->first != tag ? byTag.end() : found;
  };
  for (std::size_t f = 0; f < faceElement.size(); ++f) {
    auto found = recordOf(faceElement[f]);
    if (found == byTag.end() && !covered.element.empty() && covered.element[f] != kNoCoveredElement)
      found = recordOf(covered.element[f]);
    if (found == byTag.end()) continue;
    std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(found->second * components), components,
                perFace.begin() + static_cast<std::ptrdiff_t>(f * components));
  }
  return perFace;
}

namespace {

constexpr std::uint32_t kNoRecord = 0xFFFFFFFFu;

// Per face corner, the value recordOf(its element's tag) gives for its node, else recordOf(the
// covered volume element's tag) for the node there: nodeCount(record) nodes, their values from
// valuesOf(record) on.
template <typename RecordOf, typename NodeCount, typename ValuesOf>
std::vector<float> cornerValues(int componentCount, const std::vector<std::uint64_t>& faceElement,
                                const std::vector<MshCornerNodes>& faceCornerNode,
                                const MshCoveredElements& covered, RecordOf recordOf, NodeCount nodeCount,
                                ValuesOf valuesOf) {
  const auto components = static_cast<std::size_t>(componentCount);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> perCorner = vectorOnHugePages(faceElement.size() * kCornerSlots * components, nan);
  for (std::size_t f = 0; f < faceElement.size(); ++f) {
    std::uint32_t record = recordOf(faceElement[f]);
    const MshCornerNodes* cornerNodes = &faceCornerNode[f];
    if (record == kNoRecord) {  // a skin face's surface element without values: its volume element's
      if (covered.element.empty() || covered.element[f] == kNoCoveredElement) continue;
      record = recordOf(covered.element[f]);
      if (record == kNoRecord) continue;
      cornerNodes = &covered.cornerNode[f];
    }
    float* out = perCorner.data() + f * kCornerSlots * components;
    const MshCornerNodes& nodes = *cornerNodes;
    int added = -1;
    for (std::size_t s = 0; s < kCornerSlots; ++s) {
      if (nodes[s] == kAddedCentre) added = static_cast<int>(s);
      // No node (a triangle's fourth slot), or the record stops short of this node: NaN.
      if (nodes[s] >= nodeCount(record)) continue;
      std::copy_n(valuesOf(record) + nodes[s] * components, components, out + s * components);
    }
    if (added < 0) continue;
    // The centre lancer added to an 8-node quad (a corner of each of its four quads): the mean of
    // the other three corners of its quad, the element giving no value there.
    for (std::size_t c = 0; c < components; ++c) {
      float sum = 0;
      for (std::size_t s = 0; s < kCornerSlots; ++s)
        if (static_cast<int>(s) != added) sum += out[s * components + c];
      out[static_cast<std::size_t>(added) * components + c] = sum / 3.0f;
    }
  }
  return perCorner;
}

}  // namespace

std::vector<float> mapElementNodeValues(ElementNodeRecords records, int componentCount,
                                        const std::vector<std::uint64_t>& faceElement,
                                        const std::vector<MshCornerNodes>& faceCornerNode,
                                        const std::vector<std::pair<std::uint64_t, std::uint64_t>>& aliases,
                                        const MshCoveredElements& covered) {
  if (!aliases.empty())
    for (std::uint64_t& tag : records.tags) {
      const auto alias = std::lower_bound(aliases.begin(), aliases.end(), std::pair{tag, std::uint64_t{0}});
      if (alias != aliases.end() && alias->first == tag) tag = alias->second;
    }
  // The record of each element tag: its offset from the first when the records list consecutive
  // tags (gmsh numbers elements 1..N and writes them in order), an array over the tags' span when
  // they are dense, else sorted (tag, record) pairs searched per face.
  std::uint64_t lowTag = UINT64_MAX, highTag = 0;
  bool consecutive = true;
  for (std::size_t r = 0; r < records.tags.size(); ++r) {
    const std::uint64_t tag = records.tags[r];
    lowTag = std::min(lowTag, tag), highTag = std::max(highTag, tag);
    consecutive = consecutive && tag == records.tags.front() + r;
  }
  const bool dense = !records.tags.empty() && highTag - lowTag < 4 * records.tags.size() + 1024;
  std::vector<std::uint32_t> recordOfTag;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> byTag;
  if (!consecutive && dense) {
    recordOfTag.assign(highTag - lowTag + 1, kNoRecord);
    for (std::size_t r = 0; r < records.tags.size(); ++r)
      recordOfTag[records.tags[r] - lowTag] = static_cast<std::uint32_t>(r);
  } else if (!consecutive) {
    byTag.resize(records.tags.size());
    for (std::size_t r = 0; r < records.tags.size(); ++r)
      byTag[r] = {records.tags[r], static_cast<std::uint32_t>(r)};
    std::sort(byTag.begin(), byTag.end());
  }
  const auto recordOf = [&](std::uint64_t tag) -> std::uint32_t {
    if (consecutive)
      return tag < lowTag || tag > highTag ? kNoRecord : static_cast<std::uint32_t>(tag - lowTag);
    if (dense) return tag < lowTag || tag > highTag ? kNoRecord : recordOfTag[tag - lowTag];
    const auto found = std::lower_bound(byTag.begin(), byTag.end(), std::pair{tag, std::uint32_t{0}});
    return found == byTag.end() || found->first != tag ? kNoRecord : found->second;
  };
  return cornerValues(
      componentCount, faceElement, faceCornerNode, covered, recordOf,
      [&](std::uint32_t record) { return records.nodeCount[record]; },
      [&](std::uint32_t record) { return records.values.data() + records.firstValue[record]; });
}

std::vector<float> mapElementNodeValues(const UniformElementNodeRecords& records, int componentCount,
                                        const std::vector<std::uint64_t>& faceElement,
                                        const std::vector<MshCornerNodes>& faceCornerNode,
                                        const MshCoveredElements& covered) {
  return cornerValues(
      componentCount, faceElement, faceCornerNode, covered,
      [&](std::uint64_t tag) -> std::uint32_t {
        return tag < records.firstTag || tag - records.firstTag >= records.count
                   ? kNoRecord
                   : static_cast<std::uint32_t>(tag - records.firstTag);
      },
      [&](std::uint32_t) { return records.nodes; },
      [&](std::uint32_t record) { return records.values + record * records.stride; });
}

}  // namespace lancer
