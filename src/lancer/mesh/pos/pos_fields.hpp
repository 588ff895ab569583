// What the views of a list-based .pos file become on a mesh: each step of a view one element-node
// field (FieldAt::kCorner), its values put on the faces as $ElementNodeData records are
// (mapElementNodeValues, msh/field_mapping.hpp), whichever way the faces were tied to the view's elements.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/msh/field_mapping.hpp"
#include "lancer/mesh/pos/pos_reader.hpp"

namespace lancer {

// Where a view's elements stand among the faces' elements: per element of the view (its blocks in
// order, their elements in order), the tag of the element its faces remember (0: none: a point, a
// line, or an element no face came from), and, where the element lists its nodes in another order
// than the one the faces know, that order.
struct PosElementTags {
  std::vector<std::uint64_t> tag;
  // Empty when every element keeps its own order; else per element kSameOrder or where its order
  // starts in `order` (order[start + j]: the position of its node j in the known element).
  std::vector<std::uint32_t> orderAt;
  std::vector<std::uint8_t> order;
  static constexpr std::uint32_t kSameOrder = 0xFFFFFFFFu;
};

// Whether the elements of a block become faces (surfaces and volumes; points and lines do not).
inline bool drawnBlock(const PosElementBlock& block) { return block.kind.dimension >= 2; }

// Whether two views list the same elements in the same order at the same coordinates (GetDP's
// views of one Print region, gmsh's views of one mesh): the second can use what was made of the first.
bool sameElements(const PosView& a, const PosView& b);

// The components (1, 3 or 9) of the view's drawn blocks; 0 when it has none. Throws InputError at
// the view when they mix (a scalar and a vector list in one view).
int drawnComponents(const PosView& view, const std::string& file);

// Appends every step of `view` to mesh.fields as element-node data. Views of one name make one
// view's steps, in the order they come (gmsh's "Combine time steps by name", and what a GetDP time
// loop that appends a view per step means): a step's index follows the mesh's last step of that
// name, its time is the view's TIME value, or its step index when the view has no TIME list.
// A face whose element the view gives no values takes those of the volume element it covers
// (`covered`, may be empty: a skin face that another view's surface element made).
void addPosViewSteps(Mesh& mesh, const PosView& view, int components, const PosElementTags& elements,
                     const std::vector<std::uint64_t>& faceElement,
                     const std::vector<MshCornerNodes>& faceCornerNode,
                     const MshCoveredElements& covered = {});

}  // namespace lancer
