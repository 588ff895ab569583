// A Mesh from nodes and gmsh elements held in memory (numpy arrays, the gmsh API), built by the same
// assembler as the .msh reader: second-order faces split, volumes turned into their skin and
// interfaces, degenerate faces dropped, nodes recentred, so an array gives the mesh its file gives.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

// Elements of one gmsh type (2 triangle, 3 quad, 4 tetrahedron, ...: element_types.hpp) in one
// physical group and elementary entity; `nodes` holds nodeCount 0-based node indices per element.
struct ElementBlock {
  int type = 2;
  int dimension = 2;
  std::int32_t physical = 0;  // 0: in no physical group
  std::int32_t entity = 0;
  std::span<const std::uint32_t> nodes;
  // The elements' gmsh tags, one per element, for element fields; empty when none are given.
  std::span<const std::uint64_t> tags;
};

// Nodal values of one field (a gmsh view's step): components values per node, in node order.
struct NodeFieldInput {
  std::string name;
  int components = 1;
  std::span<const double> values;
  int step = 0;     // the view's time step index
  double time = 0;  // and its time value
};

// Values of one field per element (a gmsh view's ElementData step): components values per record,
// records named by element tag (ElementBlock::tags). Faces made from an element (its split
// second-order faces, a volume's skin faces) take its value; faces no record names get NaN.
struct ElementFieldInput {
  std::string name;
  int components = 1;
  std::span<const std::uint64_t> tags;
  std::span<const double> values;  // tags.size() * components
  int step = 0;
  double time = 0;
};

// Values of one field at each element's nodes (a gmsh view's ElementNodeData step): per record, an
// element tag, its number of nodes and that many nodes' `components` values in the element's node
// order. Each face corner takes its element's value at that node (MeshField's FieldAt::kCorner).
struct ElementNodeFieldInput {
  std::string name;
  int components = 1;
  std::span<const std::uint64_t> tags;
  std::span<const std::uint32_t> nodeCounts;  // one per tag
  std::span<const double> values;             // sum(nodeCounts) * components, record after record
  int step = 0;
  double time = 0;
};

// The caller has checked the input (finite coordinates, indices below points.size(), known types
// with whole elements): this trusts it. `name` is the mesh's name in messages. keepVolume: the
// volume elements and the fields' values inside them are kept as mesh.volume too (null when there
// are none), for slices, isosurfaces, field lines and probes of a mesh made in memory.
Mesh meshFromElements(std::span<const Vec3d> points, std::span<const ElementBlock> blocks,
                      std::vector<PhysicalGroup> namedGroups, const std::string& name,
                      std::span<const NodeFieldInput> nodeFields = {},
                      std::span<const ElementFieldInput> elementFields = {},
                      std::span<const ElementNodeFieldInput> elementNodeFields = {}, bool keepVolume = false);

// Triangles and quads already made, with a physical and an entity tag per face (lancer.Mesh from
// numpy arrays): the same mesh as the elements would give, without going element by element.
struct SurfaceFacesInput {
  std::vector<MeshFace> faces;  // corners checked by the caller: below points.size()
  std::vector<std::int32_t> physical;
  std::vector<std::int32_t> entity;
};
Mesh meshFromFaces(std::span<const Vec3d> points, SurfaceFacesInput faces,
                   std::vector<PhysicalGroup> namedGroups, const std::string& name, int threads = 0);

// Nodes per element of a gmsh element type, 0 for a type lancer does not know.
int elementNodeCount(int type);

}  // namespace lancer
