// Internal to the .msh reader: where a post-processing section's records are in the file, and what
// it takes to put them in mesh order once the mesh is assembled (the assembler fills it in finish()).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/msh/node_table.hpp"

namespace lancer {

// Where a face's corners are among its element's nodes: the order of the element's values in a
// $ElementNodeData record. kAddedCentre for a corner that is not one of the element's nodes (the
// centre lancer adds to an 8-node quad), kNoElementNode for a triangle's fourth.
inline constexpr std::uint16_t kNoElementNode = 0xFFFF;
inline constexpr std::uint16_t kAddedCentre = 0xFFFE;
using MshCornerNodes = std::array<std::uint16_t, 4>;

// The volume elements under the faces made from surface elements that cover a volume's skin: GetDP's
// -v2 output and gmsh's saved views give values on the volume elements only, and such a face takes
// them when its own element has no record (a record of the surface element, a view on the boundary,
// wins). Per face: the volume element's tag (kNoCoveredElement for a face that covers none) and where
// the face's corners are among that element's nodes, in slot order like MshFieldMapping's
// faceCornerNode. Empty when no face covers a volume element, or no element data needs it.
inline constexpr std::uint64_t kNoCoveredElement = 0;
struct MshCoveredElements {
  std::vector<std::uint64_t> element;
  std::vector<MshCornerNodes> cornerNode;
};

// One $NodeData, $ElementData or $ElementNodeData section: its header as a MeshField without values, and
// where its records are in the file.
struct MshFieldSection {
  MeshField field;
  std::uint64_t count = 0;         // records
  std::uint64_t recordsBegin = 0;  // byte offset of the first record
  std::uint64_t recordsEnd = 0;    // byte offset just past the last record
  std::uint64_t sectionBegin = 0;  // byte offset of the section's name, for messages
  bool binary = false;
};

// What it takes to put a section's records in mesh order once the mesh is assembled: the node
// lookup, the nodes the mesh kept and the quad centres lancer added (node data); the element each
// face came from (element data, only when the file has some).
struct MshFieldMapping {
  MshNodeTable nodes;                  // tags and lookup; its coordinates are released
  std::size_t nodeCount = 0;           // node-table entries: tagged nodes then derived centres
  std::vector<std::uint8_t> usedNode;  // per node-table entry: whether it became a mesh vertex
  std::uint32_t usedCount = 0;
  std::vector<std::array<std::uint32_t, 8>> derivedSources;  // corners and mids of each centre
  std::vector<std::uint64_t> faceElement;      // per mesh face, its element's tag (aliases resolved)
  std::vector<MshCornerNodes> faceCornerNode;  // per mesh face, where its corners are in its element
  MshCoveredElements covered;                  // the volume elements under skin surface elements
  std::vector<std::pair<std::uint64_t, std::uint64_t>> elementAliases;  // sorted (copy, kept)
  // Set when the caller asked for the volume: each section's values go there too.
  std::shared_ptr<class MshVolumeCapture> volume;
  std::uint64_t minElementTag = UINT64_MAX;
  std::uint64_t maxElementTag = 0;
};

// The values of an 8-node quad's centre from those of its corners and mids (serendipity), and the
// node-table values of the nodes the mesh kept, in mesh order (the assembler's own fields too).
void remapNodeValues(std::vector<float>& values, int components, const std::vector<std::uint8_t>& usedNode,
                     std::uint32_t usedCount, std::size_t tagged,
                     const std::vector<std::array<std::uint32_t, 8>>& derivedSources);
// The records of a $ElementNodeData section: per record its element's tag, where its values start
// in `values` and how many nodes they are given for (each with `components` values).
struct ElementNodeRecords {
  std::vector<std::uint64_t> tags;
  std::vector<std::uint64_t> firstValue;
  std::vector<std::uint32_t> nodeCount;
  std::vector<float> values;
};
// Per face corner (kCornerSlots per face), the value its element's record gives for that node, or
// when its element has none, the record of the volume element it covers (`covered`, may be empty);
// NaN where no record or no value is given. A corner that is not an element node (an added centre)
// gets the mean of the face's other corners.
std::vector<float> mapElementNodeValues(ElementNodeRecords records, int components,
                                        const std::vector<std::uint64_t>& faceElement,
                                        const std::vector<MshCornerNodes>& faceCornerNode,
                                        const std::vector<std::pair<std::uint64_t, std::uint64_t>>& aliases,
                                        const MshCoveredElements& covered = {});
// Records that need no copy and no table: record r is the element tagged firstTag + r, with `nodes`
// nodes of the section's components each at values + r * stride (a .pos view's block, one step of
// it read in place).
struct UniformElementNodeRecords {
  std::uint64_t firstTag = 1;
  std::size_t count = 0;
  std::uint32_t nodes = 0;
  const float* values = nullptr;
  std::size_t stride = 0;
};
// The same as above for such records.
std::vector<float> mapElementNodeValues(const UniformElementNodeRecords& records, int components,
                                        const std::vector<std::uint64_t>& faceElement,
                                        const std::vector<MshCornerNodes>& faceCornerNode,
                                        const MshCoveredElements& covered = {});
// Per face, its element's values, else those of the volume element it covers (`covered`, may be
// empty); NaN where the records have neither. Tags are resolved through the sorted aliases first.
std::vector<float> mapElementValues(std::vector<std::uint64_t> tags, const std::vector<float>& values,
                                    int components, const std::vector<std::uint64_t>& faceElement,
                                    const std::vector<std::pair<std::uint64_t, std::uint64_t>>& aliases,
                                    const MshCoveredElements& covered = {});

}  // namespace lancer
