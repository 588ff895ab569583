#include "lancer/mesh/msh/volume_capture.hpp"

#include <algorithm>
#include <limits>

namespace lancer {

void MshVolumeCapture::addCell(CellShape shape, const std::uint32_t* nodeIndex, std::uint64_t tag,
                               std::int32_t physical, std::int32_t entity) {
  std::array<std::uint32_t, kMaxCellCorners> corners;
  corners.fill(kNoVertex);
  std::copy_n(nodeIndex, cellCornerCount(shape), corners.begin());
  volume_->cells.push_back(corners);
  volume_->shapes.push_back(shape);
  volume_->cellPhysicalTag.push_back(physical);
  volume_->cellEntityTag.push_back(entity);
  cellTag_.push_back(tag);
}

void MshVolumeCapture::finishCells(std::span<const Vec3d> coords, const Vec3d& origin) {
  VolumeMesh& volume = *volume_;
  volume.origin = origin;
  // The nodes cells use, in node-table (file) order, numbered densely.
  volumeNodeOf_.assign(coords.size(), kNoVertex);
  for (const auto& cell : volume.cells)
    for (const std::uint32_t node : cell)
      if (node != kNoVertex) volumeNodeOf_[node] = 0;
  std::uint32_t next = 0;
  for (std::size_t i = 0; i < coords.size(); ++i) {
    if (volumeNodeOf_[i] == kNoVertex) continue;
    volumeNodeOf_[i] = next++;
    volume.nodes.push_back(toFloat(coords[i] - origin));
  }
  for (auto& cell : volume.cells)
    for (std::uint32_t& node : cell)
      if (node != kNoVertex) node = volumeNodeOf_[node];
  cellByTag_.reserve(cellTag_.size());
  for (std::size_t c = 0; c < cellTag_.size(); ++c)
    cellByTag_.emplace_back(cellTag_[c], static_cast<std::uint32_t>(c));
  std::sort(cellByTag_.begin(), cellByTag_.end());
}

std::uint32_t MshVolumeCapture::cellOfTag(std::uint64_t tag) const {
  const auto found =
      std::lower_bound(cellByTag_.begin(), cellByTag_.end(), std::pair<std::uint64_t, std::uint32_t>{tag, 0});
  return found != cellByTag_.end() && found->first == tag ? found->second : kNoVertex;
}

namespace {

VolumeField fieldWithoutValues(const MeshField& header) {
  VolumeField field;
  field.name = header.name;
  field.at = header.at;
  field.components = header.components;
  field.step = header.step;
  field.time = header.time;
  return field;
}

}  // namespace

void MshVolumeCapture::addNodeField(const MeshField& header, std::span<const float> tableOrderValues) {
  VolumeField field = fieldWithoutValues(header);
  const auto components = static_cast<std::size_t>(field.components);
  field.values.assign(volume_->nodes.size() * components, std::numeric_limits<float>::quiet_NaN());
  const std::size_t tableNodes = std::min(volumeNodeOf_.size(), tableOrderValues.size() / components);
  for (std::size_t i = 0; i < tableNodes; ++i) {
    const std::uint32_t node = volumeNodeOf_[i];
    if (node == kNoVertex) continue;
    std::copy_n(tableOrderValues.data() + i * components, components,
                field.values.data() + node * components);
  }
  volume_->fields.push_back(std::move(field));
}

void MshVolumeCapture::addElementField(const MeshField& header, std::span<const std::uint64_t> tags,
                                       std::span<const float> values) {
  VolumeField field = fieldWithoutValues(header);
  const auto components = static_cast<std::size_t>(field.components);
  field.values.assign(volume_->cells.size() * components, std::numeric_limits<float>::quiet_NaN());
  for (std::size_t r = 0; r < tags.size(); ++r) {
    const std::uint32_t cell = cellOfTag(tags[r]);
    if (cell == kNoVertex) continue;
    std::copy_n(values.data() + r * components, components, field.values.data() + cell * components);
  }
  volume_->fields.push_back(std::move(field));
}

void MshVolumeCapture::addElementNodeField(const MeshField& header, const ElementNodeRecords& records) {
  VolumeField field = fieldWithoutValues(header);
  const auto components = static_cast<std::size_t>(field.components);
  const std::size_t slot = kMaxCellCorners * components;
  field.values.assign(volume_->cells.size() * slot, std::numeric_limits<float>::quiet_NaN());
  for (std::size_t r = 0; r < records.tags.size(); ++r) {
    const std::uint32_t cell = cellOfTag(records.tags[r]);
    if (cell == kNoVertex) continue;
    // gmsh gives an element's values node by node in its node order: the corners come first.
    const auto corners = std::min<std::size_t>(
        records.nodeCount[r], static_cast<std::size_t>(cellCornerCount(volume_->shapes[cell])));
    std::copy_n(records.values.data() + records.firstValue[r], corners * components,
                field.values.data() + cell * slot);
  }
  volume_->fields.push_back(std::move(field));
}

}  // namespace lancer
