// A post-processing field that a .msh file carries beside its mesh ($NodeData, $ElementData or
// $ElementNodeData: one time step of one gmsh view), mapped onto the mesh lancer renders so that
// surfaces can be coloured by it. Values are float: a colour map needs no more, and a field costs 4 bytes per
// vertex and component instead of 8.
//
// A file whose steps would take much memory (fifty steps of a million-face result) leaves them in
// the file: such a step is *stored* (its `values` empty) and read back when a picture needs it
// (loadedField). The reader has already read it once, checked it and kept its ranges, so colour
// ranges over every step need no second read.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lancer {

class StoredFieldSteps;  // mesh/msh/stored_steps.hpp: reads stored steps back from their file

// Where a stored step's values are, and what the reader saw of them.
struct StoredFieldValues {
  std::shared_ptr<const StoredFieldSteps> file;
  std::size_t section = 0;  // which of the file's field sections
  std::size_t items = 0;    // vertices, faces or face corner slots
  // Set when the mesh was renumbered after reading (morton_renumbering.hpp): item i is the item
  // order[i] of the file's mesh order.
  std::shared_ptr<const std::vector<std::uint32_t>> order = nullptr;
};

// Where a field's values sit on the mesh.
enum class FieldAt : std::uint8_t {
  kNode,     // $NodeData: one value per mesh vertex, continuous across faces
  kElement,  // $ElementData: one value per face, constant over it
  // $ElementNodeData: one value per face corner (kCornerSlots per face, the last NaN for a triangle),
  // each element's own, so a field that jumps between elements (a flux density, a stress) keeps its
  // jumps, as gmsh draws it.
  kCorner,
};
inline constexpr std::size_t kCornerSlots = 4;

// The .msh section that holds such values, for messages.
inline const char* mshSectionName(FieldAt at) {
  return at == FieldAt::kNode ? "$NodeData" : at == FieldAt::kElement ? "$ElementData" : "$ElementNodeData";
}
// "node", "element" or "element-node", for `lancer info` and messages.
inline const char* fieldAtName(FieldAt at) {
  return at == FieldAt::kNode ? "node" : at == FieldAt::kElement ? "element" : "element-node";
}

struct MeshField {
  std::string name;             // the view's name (first string tag)
  FieldAt at = FieldAt::kNode;  // which items the values are given for
  int components = 1;           // 1 scalar, 3 vector, 9 tensor
  int step = 0;                 // time step index (first integer tag)
  double time = 0;              // time value (first real tag)
  // components values per mesh vertex (node data), per face (element data) or per face corner
  // (element-node data, kCornerSlots per face), in mesh order; NaN where the file gives no value
  // (e.g. the centre lancer adds to an 8-node quad). Empty while the step is stored.
  std::vector<float> values;
  std::shared_ptr<const StoredFieldValues> stored = nullptr;  // set while the values wait in the file
  // What the .msh reader saw of the values (componentRanges): the least and greatest of each
  // component, then of the magnitude, then of von Mises (a tensor), NaN ignored, low > high when
  // there is none. componentRange() and range() read them instead of every value (an animation asks
  // for the range over every step in every frame); empty for fields made otherwise.
  std::vector<std::pair<float, float>> ranges{};

  bool isStored() const { return stored != nullptr; }
  std::size_t itemCount() const {
    if (stored) return stored->items;
    return components > 0 ? values.size() / static_cast<std::size_t>(components) : 0;
  }
  // The scalar colour maps show: the value of a scalar, the length of a vector or tensor (not for
  // a stored step: load it first).
  float scalar(std::size_t item) const;
  // The least and greatest scalar over the items, ignoring NaN; {0, 0} when there is none.
  std::pair<float, float> range() const;
};

// Drops the steps a stored field's file keeps read (before a large allocation, such as a tree's
// build): they are read again when needed. Nothing for a field in memory.
void forgetKeptSteps(const MeshField& field);

// The field with its values in memory: a copy of it, read back from its file when it is stored.
// Throws InputError when the file cannot be read again or changed since it was read.
MeshField loadedField(const MeshField& field);

}  // namespace lancer
