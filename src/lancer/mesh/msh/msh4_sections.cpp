// $Entities, $PartitionedEntities, $Nodes and $Elements of MSH 4.1 (ASCII and binary) and 4.0 (ASCII;
// the reader refuses 4.0 binary, which gmsh no longer writes). Layouts from the gmsh manual, "MSH file
// format".
#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <cstring>

#include "lancer/mesh/msh/sections.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer {
namespace {

// The three value kinds of MSH 4, read as text or as raw binary (size_t, int, double).
class Msh4Values {
 public:
  explicit Msh4Values(MshReadState& state) : cursor_(state.cursor), binary_(state.binary) {}

  std::uint64_t size(const char* what) {
    return binary_ ? cursor_.readRaw<std::uint64_t>(what) : cursor_.readCount(what);
  }
  std::int32_t integer(const char* what) {
    return binary_ ? cursor_.readRaw<std::int32_t>(what) : cursor_.readInt32(what);
  }
  double real(const char* what) { return binary_ ? cursor_.readRaw<double>(what) : cursor_.readDouble(what); }
  // Checks that count values of at least valueBytes (binary) or one token (text) can follow.
  void requireValues(std::uint64_t count, std::uint64_t binaryBytes, std::uint64_t textNumbers,
                     const char* what) {
    cursor_.requireBytes(count, binary_ ? binaryBytes : textNumbers * kMinTextNumberBytes, what);
  }
  // Binary data starts after the newline that ends the section's name.
  void beginSection() {
    if (binary_) cursor_.skipLine();
  }
  const char* here() {
    if (!binary_) cursor_.skipWhitespace();
    return cursor_.position();
  }
  bool binary() const { return binary_; }

 private:
  MshCursor& cursor_;
  bool binary_;
};

void skipTagList(Msh4Values& values, const char* what) {
  const std::uint64_t count = values.size(what);
  values.requireValues(count, 4, 1, what);
  for (std::uint64_t i = 0; i < count; ++i) values.integer(what);
}

// An entity's physical groups. gmsh writes -T for a group that takes the entity with reversed
// orientation (e.g. a Physical Surface of {-2001}): that is still the group T (gmsh's own
// getPhysicalGroups reports T), so the sign is dropped, and a group listed twice counts once.
void readPhysicalTags(Msh4Values& values, MshEntity& entity) {
  const char* what = "the entity's physical groups";
  const std::uint64_t count = values.size(what);
  values.requireValues(count, 4, 1, what);
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::int32_t signedTag = values.integer(what);
    const std::int32_t tag = signedTag == INT32_MIN ? INT32_MAX : std::abs(signedTag);
    if (tag == 0 || tag == entity.physical) continue;
    if (entity.physical == 0) {
      entity.physical = tag;
    } else if (std::find(entity.morePhysicals.begin(), entity.morePhysicals.end(), tag) ==
               entity.morePhysicals.end()) {
      entity.morePhysicals.push_back(tag);
    }
  }
}

// The hot loop for the common binary blocks (3-node triangles, 4-node quads): fixed-size records
// of size_t element tag and node tags, already checked to fit in the file.
template <int kNodes>
void readBinaryElements(MshReadState& state, int type, std::uint64_t count) {
  MshCursor& cursor = state.cursor;
  const MshNodeTable& nodes = state.assembler.nodes;
  constexpr std::size_t kRecordBytes = 8 * (kNodes + 1);
  const char* data = cursor.advance(count * kRecordBytes);
  for (std::uint64_t e = 0; e < count; ++e) {
    std::uint64_t record[kNodes + 1];
    std::memcpy(record, data + e * kRecordBytes, kRecordBytes);
    std::uint32_t nodeIndex[kNodes];
    for (int n = 0; n < kNodes; ++n) {
      nodeIndex[n] = nodes.find(record[n + 1]);
      if (nodeIndex[n] == kNoVertex)
        failMissingNode(state, data + e * kRecordBytes, record[0], type, record[n + 1]);
    }
    state.assembler.addElement(type, nodeIndex, record[0]);
  }
}

// A binary block of 3-node triangles read straight into the assembler's faces (when it tracks no
// element or side): node tags become node indices in parallel chunks, and a missing node is reported
// at the first element (in file order) that names one, as the element-by-element loop would.
void readBinaryTriangles(MshReadState& state, std::uint64_t count) {
  MshMeshAssembler& assembler = state.assembler;
  const MshNodeTable& nodes = assembler.nodes;
  constexpr std::size_t kRecordBytes = 8 * 4;
  const char* data = state.cursor.advance(count * kRecordBytes);
  MeshFace* faces = assembler.addTriangles(count);
  const ChunkPlan chunks(count, 32768);
  std::vector<std::uint64_t> firstMissing(chunks.chunks, UINT64_MAX);
  parallelChunks(chunks, assembler.threads(), [&](std::size_t k, std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e) {
      std::uint64_t record[4];
      std::memcpy(record, data + e * kRecordBytes, kRecordBytes);
      MeshFace& face = faces[e];
      for (int n = 0; n < 3; ++n) face.vertex[n] = nodes.find(record[n + 1]);
      face.vertex[3] = kNoVertex;
      if ((face.vertex[0] == kNoVertex || face.vertex[1] == kNoVertex || face.vertex[2] == kNoVertex) &&
          firstMissing[k] == UINT64_MAX)
        firstMissing[k] = e;
    }
  });
  for (const std::uint64_t e : firstMissing) {
    if (e == UINT64_MAX) continue;
    std::uint64_t record[4];
    std::memcpy(record, data + e * kRecordBytes, kRecordBytes);
    for (int n = 0; n < 3; ++n)
      if (nodes.find(record[n + 1]) == kNoVertex)
        failMissingNode(state, data + e * kRecordBytes, record[0], 2, record[n + 1]);
  }
}

// A binary block of volume elements read straight into the assembler's element array: node tags
// become node indices in parallel chunks, and a missing node is reported at the first element (in
// file order) that names one, as the element-by-element loop would.
void readBinaryVolumeElements(MshReadState& state, int type, int nodeCount, std::uint64_t count) {
  MshMeshAssembler& assembler = state.assembler;
  const MshNodeTable& nodes = assembler.nodes;
  const std::uint64_t recordBytes = 8 * (static_cast<std::uint64_t>(nodeCount) + 1);
  const char* data = state.cursor.advance(count * recordBytes);
  std::uint64_t* tags = nullptr;
  std::uint32_t* out = assembler.addVolumeElements(type, count, &tags);
  const ChunkPlan chunks(count, 32768);
  std::vector<std::uint64_t> firstMissing(chunks.chunks, UINT64_MAX);
  parallelChunks(chunks, assembler.threads(), [&](std::size_t k, std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e) {
      const char* record = data + e * recordBytes;
      std::uint32_t* index = out + e * static_cast<std::size_t>(nodeCount);
      if (tags) std::memcpy(&tags[e], record, 8);
      for (int n = 0; n < nodeCount; ++n) {
        std::uint64_t tag;
        std::memcpy(&tag, record + 8 * (n + 1), 8);
        index[n] = nodes.find(tag);
        if (index[n] == kNoVertex && firstMissing[k] == UINT64_MAX) firstMissing[k] = e;
      }
    }
  });
  for (const std::uint64_t e : firstMissing) {
    if (e == UINT64_MAX) continue;
    std::uint64_t record[kMaxMshElementNodes + 1];
    std::memcpy(record, data + e * recordBytes, recordBytes);
    for (int n = 0; n < nodeCount; ++n)
      if (nodes.find(record[n + 1]) == kNoVertex)
        failMissingNode(state, data + e * recordBytes, record[0], type, record[n + 1]);
  }
}

// Binary blocks can be measured before they are read: their headers give the room the face and
// volume element arrays need, so that none grows by copies. Stops quietly at anything odd (the
// reading loop then says what is wrong); every count is checked against the bytes left first.
void reserveFromBlockHeaders(MshReadState& state, std::uint64_t blocks) {
  const char* at = state.cursor.position();
  const char* end = at + state.cursor.remaining();
  std::uint64_t faces = 0, volumeElements = 0, volumeNodes = 0;
  for (std::uint64_t b = 0; b < blocks && end - at >= 20; ++b) {
    std::int32_t type;
    std::uint64_t count;
    std::memcpy(&type, at + 8, 4);
    std::memcpy(&count, at + 12, 8);
    at += 20;
    const MshElementType info = mshElementType(type);
    if (info.nodeCount == 0) break;
    const std::uint64_t recordBytes = 8 * (static_cast<std::uint64_t>(info.nodeCount) + 1);
    if (count > static_cast<std::uint64_t>(end - at) / recordBytes) break;
    at += count * recordBytes;
    if (info.role == MshElementRole::kVolume && volumeElementFaceCount(type) > 0) {
      volumeElements += count;
      volumeNodes += count * static_cast<std::uint64_t>(info.nodeCount);
    } else if (info.role == MshElementRole::kSurface) {
      faces += count * (type == 2 || type == 3 ? 1 : 4);  // second order and up split (in 4 or more)
    }
  }
  state.assembler.reserveFaces(faces);
  state.assembler.reserveVolumeElements(volumeElements, volumeNodes);
}

}  // namespace

void readMsh4Entities(MshReadState& state, bool partitioned) {
  Msh4Values values(state);
  values.beginSection();
  if (partitioned) {
    const std::uint64_t partitions = values.size("the number of partitions");
    state.source.partitionCount = static_cast<std::uint32_t>(std::min<std::uint64_t>(partitions, UINT32_MAX));
    const std::uint64_t ghosts = values.size("the number of ghost entities");
    values.requireValues(ghosts, 8, 2, "the ghost entity list");
    for (std::uint64_t i = 0; i < ghosts; ++i) {
      values.integer("a ghost entity tag");
      values.integer("a ghost entity's partition");
    }
  }
  std::uint64_t counts[4];
  for (auto& count : counts) count = values.size("the number of entities of a dimension");
  for (int dimension = 0; dimension < 4; ++dimension) {
    values.requireValues(counts[dimension], 4 + 24 + 8, 5,
                         partitioned ? "$PartitionedEntities" : "$Entities");
    for (std::uint64_t i = 0; i < counts[dimension]; ++i) {
      const std::int32_t tag = values.integer("an entity tag");
      MshEntity entity{0, tag, {}};
      int parentDimension = -1;
      std::int32_t parentTag = 0;
      if (partitioned) {
        parentDimension = values.integer("the parent entity's dimension");
        parentTag = values.integer("the parent entity's tag");
        skipTagList(values, "the entity's partitions");
      }
      // MSH 4.1 gives a point its coordinates, 4.0 and all other entities a bounding box.
      const int coordinates = (dimension == 0 && state.minor == 1) ? 3 : 6;
      for (int k = 0; k < coordinates; ++k) values.real("an entity's bounding box");
      readPhysicalTags(values, entity);
      if (dimension > 0) skipTagList(values, "the entity's bounding entities");
      if (partitioned) {
        const auto parent = state.entities.find(mshEntityKey(parentDimension, parentTag));
        if (entity.physical == 0 && parent != state.entities.end()) {
          entity.physical = parent->second.physical;
          entity.morePhysicals = parent->second.morePhysicals;
        }
        if (parentDimension == dimension) entity.geometric = parentTag;
        state.partitionedEntities[mshEntityKey(dimension, tag)] = entity;
      } else {
        state.entities[mshEntityKey(dimension, tag)] = entity;
      }
    }
  }
  state.cursor.expectToken(partitioned ? "$EndPartitionedEntities" : "$EndEntities", "after the entities");
}

void readMsh4Nodes(MshReadState& state) {
  MshCursor& cursor = state.cursor;
  Msh4Values values(state);
  values.beginSection();
  const char* headerAt = values.here();
  const std::uint64_t blocks = values.size("the number of node blocks");
  const std::uint64_t count = values.size("the number of nodes");
  if (state.minor == 1) {
    values.size("the smallest node tag");
    values.size("the largest node tag");
  }
  values.requireValues(blocks, 20, 4, "$Nodes (blocks)");
  values.requireValues(count, 8 + 24, 4, "$Nodes");
  state.cursor.requireMemory(count, "$Nodes");
  MshNodeTable& nodes = state.assembler.nodes;
  nodes.reserve(count);
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const char* blockAt = values.here();
    int dimension = values.integer("a node block's entity dimension");
    int tag = values.integer("a node block's entity tag");
    if (state.minor == 0) std::swap(dimension, tag);
    const int parametric = values.integer("a node block's parametric flag");
    const std::uint64_t inBlock = values.size("the number of nodes in a block");
    if (inBlock > count - std::min(count, nodes.taggedCount()))
      cursor.failAt(blockAt,
                    fmt::format("node blocks hold more than the {} nodes the $Nodes header declares", count));
    // Parametric nodes carry one extra coordinate per dimension of their entity.
    const int extra = parametric ? std::clamp(dimension, 0, 3) : 0;
    const int perNode = 3 + extra;
    values.requireValues(inBlock, 8 + 8 * static_cast<std::uint64_t>(perNode), 1 + perNode, "the node block");
    if (state.binary) {
      // MSH 4.1 binary: all the block's tags, then all its coordinates (3 + extra doubles per
      // node). One pass appends both and checks finiteness: no zero-filled resize, no second pass.
      static_assert(sizeof(Vec3d) == 3 * sizeof(double), "a node's x, y, z are copied as one block");
      const std::uint64_t stride = 8 * static_cast<std::uint64_t>(perNode);
      const char* tagData = cursor.advance(8 * inBlock);
      const char* coordData = cursor.advance(stride * inBlock);
      for (std::uint64_t i = 0; i < inBlock; ++i) {
        std::uint64_t nodeTag;
        Vec3d p;
        std::memcpy(&nodeTag, tagData + 8 * i, 8);
        std::memcpy(&p, coordData + stride * i, sizeof(Vec3d));
        if (!isFinite(p)) checkFinite(state, p, nodeTag, coordData + stride * i);
        nodes.add(nodeTag, p);
      }
    } else if (state.minor == 1) {
      std::vector<std::uint64_t>& tags = nodes.tags();
      const std::size_t first = tags.size();
      for (std::uint64_t i = 0; i < inBlock; ++i) tags.push_back(cursor.readCount("a node tag"));
      std::vector<Vec3d>& coords = nodes.coords();
      for (std::uint64_t i = 0; i < inBlock; ++i) {
        const char* at = values.here();
        const Vec3d p = readTextNodeCoordinates(cursor);
        for (int k = 0; k < extra; ++k) cursor.readDouble("a parametric coordinate");
        checkFinite(state, p, tags[first + i], at);
        coords.push_back(p);
      }
    } else {
      for (std::uint64_t i = 0; i < inBlock; ++i) {
        const char* at = values.here();
        const std::uint64_t nodeTag = cursor.readCount("a node tag");
        const Vec3d p = readTextNodeCoordinates(cursor);
        for (int k = 0; k < extra; ++k) cursor.readDouble("a parametric coordinate");
        checkFinite(state, p, nodeTag, at);
        nodes.add(nodeTag, p);
      }
    }
  }
  if (nodes.taggedCount() != count)
    cursor.failAt(headerAt, fmt::format("the $Nodes header declares {} nodes, but its blocks hold {}", count,
                                        nodes.taggedCount()));
  cursor.expectToken("$EndNodes", fmt::format("after the {} nodes $Nodes declares", count).c_str());
}

void readMsh4Elements(MshReadState& state) {
  MshCursor& cursor = state.cursor;
  Msh4Values values(state);
  values.beginSection();
  const char* headerAt = values.here();
  const std::uint64_t blocks = values.size("the number of element blocks");
  const std::uint64_t count = values.size("the number of elements");
  if (state.minor == 1) {
    state.minElementTag = values.size("the smallest element tag");
    state.maxElementTag = values.size("the largest element tag");
  } else {
    state.minElementTag = 0, state.maxElementTag = UINT64_MAX;  // 4.0 headers give no tag range
  }
  values.requireValues(blocks, 20, 4, "$Elements (blocks)");
  values.requireValues(count, 16, 2, "$Elements");
  cursor.requireMemory(count, "$Elements");
  if (state.binary && state.minor == 1) {
    reserveFromBlockHeaders(state, blocks);
  } else {
    state.assembler.reserveFaces(count);
  }
  const MshNodeTable& nodes = state.assembler.nodes;
  const auto& entities = state.partitionedEntities.empty() ? state.entities : state.partitionedEntities;
  std::uint32_t nodeIndex[kMaxMshElementNodes];
  std::uint64_t record[kMaxMshElementNodes + 1] = {};  // zeroed once: the analyser cannot see copyRaw fill it
  std::uint64_t read = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const char* blockAt = values.here();
    int dimension = values.integer("an element block's entity dimension");
    int tag = values.integer("an element block's entity tag");
    if (state.minor == 0) std::swap(dimension, tag);
    const int type = values.integer("an element block's element type");
    const std::uint64_t inBlock = values.size("the number of elements in a block");
    const MshElementType info = requireKnownType(state, type, blockAt);
    if (inBlock > count - read)
      cursor.failAt(
          blockAt,
          fmt::format("element blocks hold more than the {} elements the $Elements header declares", count));
    read += inBlock;
    const auto perElement = static_cast<std::uint64_t>(info.nodeCount) + 1;
    values.requireValues(inBlock, 8 * perElement, perElement, "the element block");
    const auto entity = entities.find(mshEntityKey(dimension, tag));
    const MshEntity group = entity != entities.end() ? entity->second : MshEntity{0, tag, {}};
    state.assembler.setGroup(info.dimension, group.physical, group.geometric);
    for (const std::int32_t more : group.morePhysicals)
      state.addExtraGroup(info.dimension, group.geometric, group.physical, more);
    const bool keep = info.role == MshElementRole::kSurface || info.role == MshElementRole::kVolume;
    if (!keep && state.binary) {
      for (std::uint64_t e = 0; e < inBlock; ++e) state.assembler.countElement(type);
      cursor.advance(8 * perElement * inBlock);
      continue;
    }
    if (state.binary && type == 2) {
      if (state.assembler.takesTriangleBlocks())
        readBinaryTriangles(state, inBlock);
      else
        readBinaryElements<3>(state, type, inBlock);
      continue;
    }
    if (state.binary && type == 3) {
      readBinaryElements<4>(state, type, inBlock);
      continue;
    }
    if (state.binary && info.role == MshElementRole::kVolume && volumeElementFaceCount(type) > 0 &&
        !state.assembler.keepsVolume()) {
      readBinaryVolumeElements(state, type, info.nodeCount, inBlock);
      continue;
    }
    for (std::uint64_t e = 0; e < inBlock; ++e) {
      const char* at = values.here();
      if (state.binary) {
        cursor.copyRaw(record, perElement);
      } else {
        for (std::uint64_t k = 0; k < perElement; ++k)
          record[k] = cursor.readCount("an element's tag or node");
      }
      if (!keep) {
        state.assembler.countElement(type);
        continue;
      }
      for (int n = 0; n < info.nodeCount; ++n) {
        nodeIndex[n] = nodes.find(record[n + 1]);
        if (nodeIndex[n] == kNoVertex) failMissingNode(state, at, record[0], type, record[n + 1]);
      }
      state.assembler.addElement(type, nodeIndex, record[0]);
    }
  }
  if (read != count)
    cursor.failAt(headerAt, fmt::format("the $Elements header declares {} elements, but its blocks hold {}",
                                        count, read));
  cursor.expectToken("$EndElements", fmt::format("after the {} elements $Elements declares", count).c_str());
}

}  // namespace lancer
