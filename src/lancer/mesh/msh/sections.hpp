// Internal to the .msh reader: the state shared by the section parsers and the parsers of the
// sections whose layout depends on the MSH version (msh2_sections.cpp, msh4_sections.cpp).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/msh/cursor.hpp"
#include "lancer/mesh/msh/field_mapping.hpp"
#include "lancer/mesh/msh/mesh_assembler.hpp"

namespace lancer {

// What an MSH 4 element block's entity contributes to its faces.
struct MshEntity {
  std::int32_t physical = 0;                // first physical group, 0 if none
  std::int32_t geometric = 0;               // the model entity's tag (the parent, for a partitioned entity)
  std::vector<std::int32_t> morePhysicals;  // its further physical groups (usually none)
};

struct MshReadState {
  MshReadState(MshCursor& c, MshMeshAssembler& a, MeshSourceInfo& s) : cursor(c), assembler(a), source(s) {}

  MshCursor& cursor;
  MshMeshAssembler& assembler;
  MeshSourceInfo& source;
  int major = 0;  // 2 or 4
  int minor = 0;  // 4.0 or 4.1
  bool binary = false;
  std::vector<PhysicalGroup> namedGroups;
  std::unordered_map<std::uint64_t, MshEntity> entities;             // key: mshEntityKey(dim, tag)
  std::unordered_map<std::uint64_t, MshEntity> partitionedEntities;  // $PartitionedEntities
  bool nodesRead = false;
  bool elementsRead = false;
  // The bytes of each mesh section read ($MeshFormat, $Nodes, ...), from its name to its end marker:
  // gmsh repeats the whole mesh before each view it appends to a file, and a repeat must match.
  std::map<std::string, std::string_view, std::less<>> meshSections;
  // Entities in several physical groups (Mesh::extraPhysicalGroups), one entry per entity.
  std::vector<ExtraPhysicalGroups> extraGroups;
  // readMsh's file mapping: the pages before this are handed back to the kernel after each view's
  // step ($NodeData, $ElementData), so that a file of many steps is never resident all at once (a
  // later read of those bytes faults them in again from the file). Null for memory the caller owns.
  const char* releaseFrom = nullptr;
  // The $NodeData and $ElementData sections met, in file order: read once the mesh is assembled.
  std::vector<MshFieldSection> fieldSections;
  // Element tags of the file are within [minElementTag, maxElementTag] (for $ElementData checks).
  std::uint64_t minElementTag = UINT64_MAX;
  std::uint64_t maxElementTag = 0;

  // Records that the elements of entity (dimension, entity) are also in the group `more`.
  void addExtraGroup(int dimension, std::int32_t entity, std::int32_t first, std::int32_t more);
  // Adds a "file:line:col: warning: ..." for the user (MeshSourceInfo::warnings).
  void warnAt(const char* at, const std::string& message);
};

inline std::uint64_t mshEntityKey(int dimension, std::int32_t tag) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(dimension)) << 32) |
         static_cast<std::uint32_t>(tag);
}

// Fewest bytes an ASCII number takes (one digit and one separator), for the count checks.
inline constexpr std::uint64_t kMinTextNumberBytes = 2;

void readMsh2Nodes(MshReadState& state);
void readMsh2Elements(MshReadState& state);
void readMsh4Entities(MshReadState& state, bool partitioned);
void readMsh4Nodes(MshReadState& state);
void readMsh4Elements(MshReadState& state);

// Shared by both versions: builds the node lookup after $Nodes, refusing duplicated tags.
void finishNodes(MshReadState& state, const char* sectionStart);
// Refuses a non-finite coordinate; `at` is where the node's record starts.
void checkFinite(const MshReadState& state, const Vec3d& p, std::uint64_t tag, const char* at);
// A node's x, y, z in a text $Nodes section (every version writes them the same way).
inline Vec3d readTextNodeCoordinates(MshCursor& cursor) {
  Vec3d p;
  p.x = cursor.readDouble("the node's x coordinate");
  p.y = cursor.readDouble("the node's y coordinate");
  p.z = cursor.readDouble("the node's z coordinate");
  return p;
}
// The error for an element naming a node that $Nodes does not define.
[[noreturn]] void failMissingNode(const MshReadState& state, const char* at, std::uint64_t elementTag,
                                  int type, std::uint64_t nodeTag);
// Refuses element types whose node count lancer does not know.
MshElementType requireKnownType(const MshReadState& state, int type, const char* at);

}  // namespace lancer
