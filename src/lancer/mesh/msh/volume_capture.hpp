// Internal to the .msh reader: keeps the volume elements and the values fields give inside them
// (mesh/volume/volume_mesh.hpp) while the surface is assembled, when the caller asked for the volume.
// The assembler hands it each volume element; the field readers hand it each section's values in
// the file's terms (node-table order, element tags, element-node records) before they are mapped
// onto the surface.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "lancer/mesh/msh/field_mapping.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"

namespace lancer {

class MshVolumeCapture {
 public:
  // A volume element: nodeIndex into the node table (its corners first, as gmsh lists them).
  void addCell(CellShape shape, const std::uint32_t* nodeIndex, std::uint64_t tag, std::int32_t physical,
               std::int32_t entity);
  // Once every node and element is read: the cells' nodes from the node table's double coordinates,
  // relative to the surface mesh's origin.
  void finishCells(std::span<const Vec3d> coords, const Vec3d& origin);
  // A field's values in node-table order (node data), per record with its element tags (element
  // data) or as element-node records. `header` is the field without values.
  void addNodeField(const MeshField& header, std::span<const float> tableOrderValues);
  void addElementField(const MeshField& header, std::span<const std::uint64_t> tags,
                       std::span<const float> values);
  void addElementNodeField(const MeshField& header, const ElementNodeRecords& records);
  bool empty() const { return volume_->cells.empty(); }
  std::shared_ptr<const VolumeMesh> take() { return std::move(volume_); }

 private:
  // The cell with this element tag, or kNoVertex (a record for a surface element, a line, a point).
  std::uint32_t cellOfTag(std::uint64_t tag) const;

  std::shared_ptr<VolumeMesh> volume_ = std::make_shared<VolumeMesh>();
  std::vector<std::uint64_t> cellTag_;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> cellByTag_;  // sorted, built by finishCells
  std::vector<std::uint32_t> volumeNodeOf_;                         // node-table index -> volume node
};

}  // namespace lancer
