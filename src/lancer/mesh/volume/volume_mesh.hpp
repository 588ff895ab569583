// The volume elements of a mesh and the fields given on them, kept beside the surface lancer draws
// when a picture needs the inside: a slice, an isosurface, field lines, a probe. Only the elements'
// corners are kept (a second-order element is taken linear on its corners, as its skin's colours
// are): tetrahedra, hexahedra, prisms and pyramids in gmsh's corner order.
//
// Reading it is asked for (MshReadOptions::keepVolume): a render of the skin alone needs none of it,
// and it takes about 40 bytes per tetrahedron plus the fields at every node.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "lancer/math/vec3.hpp"
#include "lancer/mesh/mesh_field.hpp"

namespace lancer {

enum class CellShape : std::uint8_t { kTetrahedron, kHexahedron, kPrism, kPyramid };

inline constexpr int kMaxCellCorners = 8;

inline constexpr int cellCornerCount(CellShape shape) {
  switch (shape) {
    case CellShape::kTetrahedron:
      return 4;
    case CellShape::kHexahedron:
      return 8;
    case CellShape::kPrism:
      return 6;
    case CellShape::kPyramid:
      break;
  }
  return 5;
}

const char* cellShapeName(CellShape shape);

// One step of one field on the volume: the same view and step as a Mesh field, with values where
// the volume needs them: `components` per volume node (node data), per cell (element data) or per
// cell corner, kMaxCellCorners slots per cell in gmsh's corner order (element-node data). NaN where
// the file gives none.
struct VolumeField {
  std::string name;
  FieldAt at = FieldAt::kNode;
  int components = 1;
  int step = 0;
  double time = 0;
  std::vector<float> values;
};

struct VolumeMesh {
  // Positions are float relative to origin, which is the surface mesh's (a point of one is a point
  // of the other).
  Vec3d origin;
  std::vector<Vec3> nodes;
  std::vector<std::array<std::uint32_t, kMaxCellCorners>> cells;  // corner nodes; kNoVertex past the last
  std::vector<CellShape> shapes;
  std::vector<std::int32_t> cellPhysicalTag;  // first physical group, 0 if none
  std::vector<std::int32_t> cellEntityTag;
  std::vector<VolumeField> fields;  // in the order the file gives them

  std::size_t cellCount() const { return cells.size(); }
  bool empty() const { return cells.empty(); }
  // The field step with this name and step index, or null.
  const VolumeField* findField(const std::string& name, int step) const;
  // The steps of the field with this name, in file order.
  std::vector<const VolumeField*> fieldSteps(const std::string& name) const;
  // The fields' names, each once, in file order ("f, u, dipole"; "none"), for messages.
  std::string fieldNameList() const;
};

// The field at the nodes: node data as it is; element and element-node data as the mean of the
// values the cells around each node give it (what ParaView's Cell Data to Point Data does), for what
// needs one value per node (an isosurface that is watertight and smooth).
VolumeField nodeMeans(const VolumeMesh& volume, const VolumeField& field);

// The steps of field `name` on their timeline, as the surface's views (mesh/field_steps.hpp): in time
// order with their times when these increase with the step index, else in step order with the step
// indices as times (a Newmark scheme's repeated t = 0, eigenmodes' unsorted frequencies).
std::vector<std::pair<double, const VolumeField*>> volumeFieldTimeline(const VolumeMesh& volume,
                                                                       const std::string& name);
// Field `name` at `time` on that timeline: the step there, the two steps around it blended linearly
// (the step before when their values differ in kind or count), or the first or last step outside
// them. Throws
// std::invalid_argument when the volume has no such field.
VolumeField volumeFieldAt(const VolumeMesh& volume, const std::string& name, double time);

}  // namespace lancer
