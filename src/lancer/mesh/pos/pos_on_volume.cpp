#include "lancer/mesh/pos/pos_on_volume.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <limits>
#include <optional>

#include "lancer/mesh/pos/point_index.hpp"
#include "lancer/mesh/pos/pos_fields.hpp"

namespace lancer {
namespace {

// The shape of a list's elements, from the order of gmsh's codes (P L T Q S H I Y); none for points,
// lines and surfaces.
std::optional<CellShape> cellShapeOf(const PosElementKind& kind) {
  switch (kind.shape) {
    case 4:
      return CellShape::kTetrahedron;
    case 5:
      return CellShape::kHexahedron;
    case 6:
      return CellShape::kPrism;
    case 7:
      return CellShape::kPyramid;
    default:
      return std::nullopt;
  }
}

// The volume's cells by their corners: the nodes numbered by position (points at the same
// coordinates are one), and per node the cells that have it as a corner.
class CellsByCorner {
 public:
  explicit CellsByCorner(const VolumeMesh& volume) : volume_(volume), nodes_(volume.nodes.size()) {
    canonical_.reserve(volume.nodes.size());
    for (const Vec3& p : volume.nodes) canonical_.push_back(nodes_.insert(p));
    start_.assign(nodes_.size() + 1, 0);
    for (std::size_t c = 0; c < volume.cells.size(); ++c)
      for (int k = 0; k < cellCornerCount(volume.shapes[c]); ++k) ++start_[corner(c, k) + 1];
    for (std::size_t n = 0; n < nodes_.size(); ++n) start_[n + 1] += start_[n];
    cells_.resize(start_.back());
    std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
    for (std::size_t c = 0; c < volume.cells.size(); ++c)
      for (int k = 0; k < cellCornerCount(volume.shapes[c]); ++k)
        cells_[next[corner(c, k)]++] = static_cast<std::uint32_t>(c);
  }

  // The cell of `shape` whose corners are at the element's corners `xyz` (x, y, z each, relative to
  // the volume's origin once made float), and in `position` where each of those corners is among the
  // cell's; kNoVertex when no cell is.
  std::uint32_t match(CellShape shape, const double* xyz, const Vec3d& origin,
                      std::array<std::uint8_t, kMaxCellCorners>& position) const {
    const int corners = cellCornerCount(shape);
    std::array<std::uint32_t, kMaxCellCorners> node;
    for (int j = 0; j < corners; ++j) {
      node[static_cast<std::size_t>(j)] =
          nodes_.find(toFloat(Vec3d{xyz[3 * j], xyz[3 * j + 1], xyz[3 * j + 2]} - origin));
      if (node[static_cast<std::size_t>(j)] == PointIndex<float>::kNone) return kNoVertex;
    }
    for (std::size_t i = start_[node[0]]; i < start_[node[0] + 1]; ++i) {
      const std::uint32_t cell = cells_[i];
      if (volume_.shapes[cell] != shape) continue;
      bool same = true;
      for (int j = 0; j < corners && same; ++j) {
        int k = 0;
        while (k < corners && corner(cell, k) != node[static_cast<std::size_t>(j)]) ++k;
        same = k < corners;
        position[static_cast<std::size_t>(j)] = static_cast<std::uint8_t>(k);
      }
      if (same) return cell;
    }
    return kNoVertex;
  }

 private:
  std::uint32_t corner(std::size_t cell, int k) const {
    return canonical_[volume_.cells[cell][static_cast<std::size_t>(k)]];
  }

  const VolumeMesh& volume_;
  PointIndex<float> nodes_;
  std::vector<std::uint32_t> canonical_;  // per volume node, its number by position
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> cells_;
};

int nextStepIndex(const std::vector<VolumeField>& fields, const std::string& name) {
  int next = 0;
  for (const VolumeField& field : fields)
    if (field.name == name) next = std::max(next, field.step + 1);
  return next;
}

// Where a view's volume elements are among the cells: per element (volume blocks in order), its
// cell (kNoVertex: none) and where its corners are among the cell's.
struct ElementCells {
  std::vector<std::uint32_t> cell;
  std::vector<std::array<std::uint8_t, kMaxCellCorners>> position;
  std::size_t matched = 0;
  std::size_t elements = 0;
};

ElementCells matchElements(const PosView& view, const VolumeMesh& volume, const CellsByCorner& cells) {
  ElementCells result;
  for (const PosElementBlock& block : view.blocks) {
    const std::optional<CellShape> shape = cellShapeOf(block.kind);
    if (!shape) continue;
    for (std::size_t e = 0; e < block.elementCount(); ++e) {
      const double* xyz = block.coords.data() + e * 3 * static_cast<std::size_t>(block.kind.nodes);
      std::array<std::uint8_t, kMaxCellCorners> position{};
      const std::uint32_t cell = cells.match(*shape, xyz, volume.origin, position);
      result.cell.push_back(cell);
      result.position.push_back(position);
      result.matched += cell != kNoVertex;
      ++result.elements;
    }
  }
  return result;
}

}  // namespace

void addPosViews(VolumeMesh& volume, const PosFile& pos) {
  if (volume.empty()) return;
  const CellsByCorner cells(volume);
  for (const PosView& view : pos.views) {
    const int components = drawnComponents(view, pos.file);
    if (components == 0) continue;
    const ElementCells elements = matchElements(view, volume, cells);
    if (elements.elements == 0) continue;
    if (elements.matched == 0)
      throw InputError(SourceLocation{pos.file, view.line},
                       fmt::format("view \"{}\" has {} volume elements, and none has the corners of a volume "
                                   "element of the mesh; give the mesh the view was computed on (the .msh "
                                   "the solver read), or draw the view on its own elements: lancer render {}",
                                   view.name, elements.elements, pos.file));
    const int firstStep = nextStepIndex(volume.fields, view.name);
    const auto perCorner = static_cast<std::size_t>(components);
    const std::size_t perCell = kMaxCellCorners * perCorner;
    for (int k = 0; k < view.stepCount; ++k) {
      VolumeField field;
      field.name = view.name;
      field.at = FieldAt::kCorner;
      field.components = components;
      field.step = firstStep + k;
      field.time = view.timesGiven ? view.times[static_cast<std::size_t>(k)] : field.step;
      field.values.assign(volume.cellCount() * perCell, std::numeric_limits<float>::quiet_NaN());
      std::size_t element = 0;
      for (const PosElementBlock& block : view.blocks) {
        const std::optional<CellShape> shape = cellShapeOf(block.kind);
        if (!shape) continue;
        for (std::size_t e = 0; e < block.elementCount(); ++e, ++element) {
          const std::uint32_t cell = elements.cell[element];
          if (cell == kNoVertex) continue;
          // The corners come first among an element's nodes (second order: its corners' values).
          const float* from = view.elementValues(block, e, k);
          for (int j = 0; j < cellCornerCount(*shape); ++j)
            std::copy_n(from + static_cast<std::size_t>(j) * perCorner, perCorner,
                        field.values.data() + cell * perCell +
                            elements.position[element][static_cast<std::size_t>(j)] * perCorner);
        }
      }
      volume.fields.push_back(std::move(field));
    }
  }
}

}  // namespace lancer
