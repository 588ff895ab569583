// $Nodes and $Elements of MSH 2.2 (gmsh manual, "MSH file format version 2 (legacy)"), ASCII and binary.
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

#include <unordered_set>

#include "lancer/mesh/msh/sections.hpp"

namespace lancer {
namespace {

// MSH 2 writes an element once per physical group it belongs to; lancer keeps the first copy.
class SeenElementTags {
 public:
  // True the first time a tag is seen.
  bool insert(std::int64_t tag) {
    if (tag >= 0 && tag < (std::int64_t{1} << 28)) {
      const auto word = static_cast<std::size_t>(tag >> 6);
      if (word >= bits_.size()) bits_.resize(std::max(word + 1, bits_.size() * 2), 0);
      const std::uint64_t bit = std::uint64_t{1} << (tag & 63);
      if (bits_[word] & bit) return false;
      bits_[word] |= bit;
      return true;
    }
    return others_.insert(tag).second;
  }

 private:
  std::vector<std::uint64_t> bits_;
  std::unordered_set<std::int64_t> others_;
};

struct Msh2Element {
  std::int64_t tag;
  int type;
  std::int32_t physical;
  std::int32_t entity;
  std::int32_t partitions;  // highest partition id in the tags, 0 if none
};

// gmsh 4 writes an MSH 2 element once per physical group, each copy with a new tag, one after the
// other (a group that takes the entity reversed gets the nodes in reverse order); older writers
// repeat the tag. The first copy is kept, and the copies' groups become the entity's further groups
// (Mesh::extraPhysicalGroups), as MSH 4 lists them in $Entities.
class Msh2ElementSink {
 public:
  explicit Msh2ElementSink(MshReadState& state) : state_(state) {}

  void add(const Msh2Element& element, const MshElementType& info, const std::uint64_t* nodeTags,
           const char* at) {
    const auto nodeCount = static_cast<std::size_t>(info.nodeCount);
    const auto tag = static_cast<std::uint64_t>(element.tag);
    state_.minElementTag = std::min(state_.minElementTag, tag);
    state_.maxElementTag = std::max(state_.maxElementTag, tag);
    std::uint64_t nodeSum = 0;
    for (std::size_t n = 0; n < nodeCount; ++n) nodeSum += nodeTags[n];
    const bool repeat = element.type == previousType_ && element.entity == previousEntity_ &&
                        nodeSum == previousNodeSum_ && sameNodes(nodeTags, nodeCount);
    const bool tagSeen = !seen_.insert(element.tag);
    if (tagSeen || repeat) {
      ++state_.source.duplicateElementsSkipped;
      // gmsh's $ElementData names the last copy: its values belong to the kept one.
      if (repeat) state_.assembler.aliasElement(tag, previousTag_);
      if ((repeat || element.entity == previousEntity_) && element.physical != previousPhysical_ &&
          element.physical != lastExtra_) {
        state_.addExtraGroup(info.dimension, element.entity, previousPhysical_, element.physical);
        lastExtra_ = element.physical;
      }
      return;
    }
    previousTag_ = tag;
    previousType_ = element.type;
    previousEntity_ = element.entity;
    previousPhysical_ = element.physical;
    lastExtra_ = 0;
    previousNodeSum_ = nodeSum;
    previousNodes_.assign(nodeTags, nodeTags + nodeCount);
    if (element.partitions > 0)
      state_.source.partitionCount =
          std::max(state_.source.partitionCount, static_cast<std::uint32_t>(element.partitions));
    if (info.role != MshElementRole::kSurface && info.role != MshElementRole::kVolume) {
      state_.assembler.countElement(element.type);
      return;
    }
    for (std::size_t n = 0; n < nodeCount; ++n) {
      nodeIndex_[n] = state_.assembler.nodes.find(nodeTags[n]);
      if (nodeIndex_[n] == kNoVertex)
        failMissingNode(state_, at, static_cast<std::uint64_t>(element.tag), element.type, nodeTags[n]);
    }
    state_.assembler.setGroup(info.dimension, element.physical, element.entity);
    state_.assembler.addElement(element.type, nodeIndex_, static_cast<std::uint64_t>(element.tag));
  }

 private:
  // The same nodes as the previous element, in its order or any other (a reversed copy).
  bool sameNodes(const std::uint64_t* nodeTags, std::size_t nodeCount) {
    if (std::equal(nodeTags, nodeTags + nodeCount, previousNodes_.begin(), previousNodes_.end())) return true;
    sortedNodes_.assign(nodeTags, nodeTags + nodeCount);
    std::sort(sortedNodes_.begin(), sortedNodes_.end());
    std::vector<std::uint64_t> previous = previousNodes_;
    std::sort(previous.begin(), previous.end());
    return sortedNodes_ == previous;
  }

  MshReadState& state_;
  SeenElementTags seen_;
  int previousType_ = 0;
  std::uint64_t previousTag_ = 0;
  std::int32_t previousEntity_ = 0;
  std::int32_t previousPhysical_ = 0;
  std::int32_t lastExtra_ = 0;  // the last further group recorded for the kept element's entity
  std::vector<std::uint64_t> previousNodes_;
  std::uint64_t previousNodeSum_ = 0;  // a cheap first test: most elements are not copies
  std::vector<std::uint64_t> sortedNodes_;
  std::uint32_t nodeIndex_[kMaxMshElementNodes];
};

}  // namespace

void readMsh2Nodes(MshReadState& state) {
  MshCursor& cursor = state.cursor;
  const std::uint64_t count = cursor.readCount("the number of nodes");
  MshNodeTable& nodes = state.assembler.nodes;
  if (state.binary) {
    cursor.skipLine();
    constexpr std::uint64_t kRecord = 4 + 3 * 8;  // int tag, 3 doubles
    cursor.requireBytes(count, kRecord, "$Nodes");
    cursor.requireMemory(count, "$Nodes");
    nodes.reserve(count);
    for (std::uint64_t i = 0; i < count; ++i) {
      const char* at = cursor.advance(kRecord);
      std::int32_t tag;
      Vec3d p;
      std::memcpy(&tag, at, 4);
      std::memcpy(&p, at + 4, 24);
      checkFinite(state, p, static_cast<std::uint64_t>(tag), at);
      nodes.add(static_cast<std::uint64_t>(tag), p);
    }
  } else {
    cursor.requireBytes(count, 4 * kMinTextNumberBytes, "$Nodes");
    cursor.requireMemory(count, "$Nodes");
    nodes.reserve(count);
    for (std::uint64_t i = 0; i < count; ++i) {
      const char* at = cursor.tokenStart();
      const std::uint64_t tag = cursor.readCount("a node tag");
      const Vec3d p = readTextNodeCoordinates(cursor);
      checkFinite(state, p, tag, at);
      nodes.add(tag, p);
    }
  }
  cursor.expectToken("$EndNodes", fmt::format("after the {} nodes $Nodes declares", count).c_str());
}

void readMsh2Elements(MshReadState& state) {
  MshCursor& cursor = state.cursor;
  const std::uint64_t count = cursor.readCount("the number of elements");
  Msh2ElementSink sink(state);
  std::uint64_t nodeTags[kMaxMshElementNodes];
  if (state.binary) {
    cursor.skipLine();
    cursor.requireBytes(count, 4 * 4, "$Elements");
    cursor.requireMemory(count, "$Elements");
    state.assembler.reserveFaces(count);
    std::vector<std::int32_t> record;
    for (std::uint64_t done = 0; done < count;) {
      const char* headerAt = cursor.position();
      const auto type = cursor.readRaw<std::int32_t>("an element block header");
      const auto inBlock = cursor.readRaw<std::int32_t>("an element block header");
      const auto tagCount = cursor.readRaw<std::int32_t>("an element block header");
      const MshElementType info = requireKnownType(state, type, headerAt);
      if (inBlock <= 0 || tagCount < 0 || static_cast<std::uint64_t>(inBlock) > count - done)
        cursor.failAt(headerAt,
                      fmt::format("element block of {} elements with {} tags does not fit the {} elements "
                                  "$Elements declares",
                                  inBlock, tagCount, count));
      const std::uint64_t values =
          1 + static_cast<std::uint64_t>(tagCount) + static_cast<std::uint64_t>(info.nodeCount);
      cursor.requireBytes(static_cast<std::uint64_t>(inBlock), values * 4, "the element block");
      record.resize(values);
      for (std::int32_t e = 0; e < inBlock; ++e) {
        const char* at = cursor.position();
        cursor.copyRaw(record.data(), values);
        const std::int32_t* tags = record.data() + 1;
        Msh2Element element{record[0], type, tagCount > 0 ? std::abs(tags[0]) : 0, tagCount > 1 ? tags[1] : 0,
                            0};
        for (int k = 3; k < tagCount; ++k)
          element.partitions = std::max(element.partitions, std::abs(tags[k]));
        for (int n = 0; n < info.nodeCount; ++n)
          nodeTags[n] = static_cast<std::uint64_t>(static_cast<std::uint32_t>(tags[tagCount + n]));
        sink.add(element, info, nodeTags, at);
      }
      done += static_cast<std::uint64_t>(inBlock);
    }
  } else {
    cursor.requireBytes(count, 4 * kMinTextNumberBytes, "$Elements");
    cursor.requireMemory(count, "$Elements");
    state.assembler.reserveFaces(count);
    for (std::uint64_t i = 0; i < count; ++i) {
      const char* at = cursor.tokenStart();
      Msh2Element element{};
      element.tag = cursor.readInt64("an element tag");
      const char* typeAt = cursor.tokenStart();
      element.type = cursor.readInt32("an element type");
      const MshElementType info = requireKnownType(state, element.type, typeAt);
      const char* tagCountAt = cursor.tokenStart();
      const std::int64_t tagCount = cursor.readInt64("the number of element tags");
      if (tagCount < 0 || tagCount > 1000)
        cursor.failAt(tagCountAt, fmt::format("element {} has {} tags; expected a small non-negative number",
                                              element.tag, tagCount));
      for (std::int64_t k = 0; k < tagCount; ++k) {
        const std::int64_t value = cursor.readInt64("an element tag value");
        if (k == 0) element.physical = static_cast<std::int32_t>(std::abs(value));
        if (k == 1) element.entity = static_cast<std::int32_t>(value);
        if (k >= 3)
          element.partitions =
              std::max<std::int32_t>(element.partitions, static_cast<std::int32_t>(std::abs(value)));
      }
      for (int n = 0; n < info.nodeCount; ++n) nodeTags[n] = cursor.readCount("a node tag of the element");
      sink.add(element, info, nodeTags, at);
    }
  }
  cursor.expectToken("$EndElements", fmt::format("after the {} elements $Elements declares", count).c_str());
}

}  // namespace lancer
