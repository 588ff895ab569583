#include "lancer/mesh/volume/volume_locator.hpp"

#include <algorithm>
#include <cmath>

namespace lancer {
namespace {

constexpr std::uint32_t kOutside = 0xFFFFFFFFu;

Vec3d cornerPosition(const VolumeMesh& volume, std::uint32_t cell, int corner) {
  return toDouble(volume.nodes[volume.cells[cell][static_cast<std::size_t>(corner)]]);
}

Vec3d cellCentre(const VolumeMesh& volume, std::uint32_t cell) {
  const int corners = cellCornerCount(volume.shapes[cell]);
  Vec3d sum{};
  for (int k = 0; k < corners; ++k) sum = sum + cornerPosition(volume, cell, k);
  return sum * (1.0 / corners);
}

double determinant(const Vec3d& a, const Vec3d& b, const Vec3d& c) { return dot(a, cross(b, c)); }

}  // namespace

void cellPointValues(const VolumeMesh& volume, const VolumeField& field, std::uint32_t cell, float* out) {
  const auto components = static_cast<std::size_t>(field.components);
  const int corners = cellCornerCount(volume.shapes[cell]);
  for (std::size_t c = 0; c < components; ++c) {
    double sum = 0;
    for (int k = 0; k < corners; ++k) {
      float value = 0;
      switch (field.at) {
        case FieldAt::kNode:
          value = field.values[volume.cells[cell][static_cast<std::size_t>(k)] * components + c];
          break;
        case FieldAt::kElement:
          value = field.values[cell * components + c];
          break;
        case FieldAt::kCorner:
          value = field.values[(cell * kMaxCellCorners + static_cast<std::size_t>(k)) * components + c];
          break;
      }
      out[static_cast<std::size_t>(k) * components + c] = value;
      sum += value;
    }
    out[kCellCentre * components + c] = static_cast<float>(sum / corners);
  }
}

VolumeLocator::VolumeLocator(const VolumeMesh& volume) : volume_(volume) {
  for (const Vec3& node : volume.nodes) bounds_.extend(toDouble(node));
  const std::size_t cells = volume.cells.size();
  buildNodeCells();
  if (cells == 0) {
    binStart_.assign(2, 0);
    return;
  }
  // About one cell per bin, the bins as cubic as the box allows (a flat box gets one layer).
  const Vec3d extent = bounds_.upper - bounds_.lower;
  const double largest = std::max({extent.x, extent.y, extent.z});
  const double floor = largest * 1e-6 + 1e-300;
  const double volumeOfBox =
      std::max(extent.x, floor) * std::max(extent.y, floor) * std::max(extent.z, floor);
  const double side = std::cbrt(volumeOfBox / static_cast<double>(cells));
  for (int axis = 0; axis < 3; ++axis) {
    const double length = extent[axis];
    dims_[static_cast<std::size_t>(axis)] =
        static_cast<int>(std::clamp(std::ceil(length / side), 1.0, 1024.0));
    binSize_[axis] = std::max(length, floor) / dims_[static_cast<std::size_t>(axis)];
  }
  const auto binOf = [&](const Vec3d& p, int axis) {
    const double t = (p[axis] - bounds_.lower[axis]) / binSize_[axis];
    return std::clamp(static_cast<int>(t), 0, dims_[static_cast<std::size_t>(axis)] - 1);
  };
  const std::size_t binCount = static_cast<std::size_t>(dims_[0]) * static_cast<std::size_t>(dims_[1]) *
                               static_cast<std::size_t>(dims_[2]);
  std::vector<std::array<int, 6>> ranges(cells);
  binStart_.assign(binCount + 1, 0);
  for (std::uint32_t cell = 0; cell < cells; ++cell) {
    Aabbd box;
    for (int k = 0; k < cellCornerCount(volume.shapes[cell]); ++k)
      box.extend(cornerPosition(volume, cell, k));
    auto& range = ranges[cell];
    for (int axis = 0; axis < 3; ++axis) {
      range[static_cast<std::size_t>(axis)] = binOf(box.lower, axis);
      range[static_cast<std::size_t>(axis + 3)] = binOf(box.upper, axis);
    }
    for (int z = range[2]; z <= range[5]; ++z)
      for (int y = range[1]; y <= range[4]; ++y)
        for (int x = range[0]; x <= range[3]; ++x)
          ++binStart_[(static_cast<std::size_t>(z) * static_cast<std::size_t>(dims_[1]) +
                       static_cast<std::size_t>(y)) *
                          static_cast<std::size_t>(dims_[0]) +
                      static_cast<std::size_t>(x) + 1];
  }
  for (std::size_t b = 0; b < binCount; ++b) binStart_[b + 1] += binStart_[b];
  binCells_.resize(binStart_.back());
  std::vector<std::uint32_t> next(binStart_.begin(), binStart_.end() - 1);
  for (std::uint32_t cell = 0; cell < cells; ++cell) {
    const auto& range = ranges[cell];
    for (int z = range[2]; z <= range[5]; ++z)
      for (int y = range[1]; y <= range[4]; ++y)
        for (int x = range[0]; x <= range[3]; ++x)
          binCells_[next[(static_cast<std::size_t>(z) * static_cast<std::size_t>(dims_[1]) +
                          static_cast<std::size_t>(y)) *
                             static_cast<std::size_t>(dims_[0]) +
                         static_cast<std::size_t>(x)]++] = cell;
  }
}

void VolumeLocator::buildNodeCells() {
  nodeCellStart_.assign(volume_.nodes.size() + 1, 0);
  for (const auto& cell : volume_.cells)
    for (const std::uint32_t node : cell)
      if (node != kOutside) ++nodeCellStart_[node + 1];
  for (std::size_t n = 0; n < volume_.nodes.size(); ++n) nodeCellStart_[n + 1] += nodeCellStart_[n];
  nodeCells_.resize(nodeCellStart_.back());
  std::vector<std::uint32_t> next(nodeCellStart_.begin(), nodeCellStart_.end() - 1);
  for (std::uint32_t c = 0; c < volume_.cells.size(); ++c)
    for (const std::uint32_t node : volume_.cells[c])
      if (node != kOutside) nodeCells_[next[node]++] = c;
}

bool VolumeLocator::locateInCell(const Vec3d& point, std::uint32_t cell, CellPoint& found) const {
  const CellShape shape = volume_.shapes[cell];
  const CellTetrahedra split = cellTetrahedra(shape, volume_.cells[cell]);
  const bool needsCentre = shape == CellShape::kHexahedron || shape == CellShape::kPrism;
  const Vec3d centre = needsCentre ? cellCentre(volume_, cell) : Vec3d{};
  const auto position = [&](std::uint8_t p) {
    return p == kCellCentre ? centre : cornerPosition(volume_, cell, p);
  };
  for (int t = 0; t < split.count; ++t) {
    const auto& tet = split.tetrahedra[static_cast<std::size_t>(t)];
    const Vec3d a = position(tet[0]);
    const Vec3d ab = position(tet[1]) - a, ac = position(tet[2]) - a, ad = position(tet[3]) - a;
    const double whole = determinant(ab, ac, ad);
    if (whole == 0) continue;
    const Vec3d ap = point - a;
    const double w1 = determinant(ap, ac, ad) / whole;
    const double w2 = determinant(ab, ap, ad) / whole;
    const double w3 = determinant(ab, ac, ap) / whole;
    const double w0 = 1 - w1 - w2 - w3;
    constexpr double kSlack = -1e-9;
    if (w0 < kSlack || w1 < kSlack || w2 < kSlack || w3 < kSlack) continue;
    found.cell = cell;
    found.points = tet;
    found.weights = {w0, w1, w2, w3};
    return true;
  }
  return false;
}

bool VolumeLocator::walk(const Vec3d& point, std::uint32_t cell, CellPoint& found) const {
  // A few steps through tetrahedra, each across the face the point lies beyond (its most negative
  // barycentric coordinate); a step onto another shape or out of the mesh gives up.
  constexpr int kSteps = 8;
  for (int step = 0; step < kSteps; ++step) {
    if (volume_.shapes[cell] != CellShape::kTetrahedron) return false;
    const auto& corners = volume_.cells[cell];
    const Vec3d a = toDouble(volume_.nodes[corners[0]]);
    const Vec3d ab = toDouble(volume_.nodes[corners[1]]) - a, ac = toDouble(volume_.nodes[corners[2]]) - a,
                ad = toDouble(volume_.nodes[corners[3]]) - a;
    const double whole = determinant(ab, ac, ad);
    if (whole == 0) return false;
    const Vec3d ap = point - a;
    const double w1 = determinant(ap, ac, ad) / whole, w2 = determinant(ab, ap, ad) / whole,
                 w3 = determinant(ab, ac, ap) / whole;
    const std::array<double, 4> w{1 - w1 - w2 - w3, w1, w2, w3};
    const int out = static_cast<int>(std::min_element(w.begin(), w.end()) - w.begin());
    if (w[static_cast<std::size_t>(out)] >= -1e-9) {
      found.cell = cell;
      found.points = {0, 1, 2, 3};
      found.weights = w;
      return true;
    }
    // The cell across the face opposite corner `out`: the other cell around its first node that holds
    // its other two nodes too.
    std::array<std::uint32_t, 3> face{};
    for (int k = 0, n = 0; k < 4; ++k)
      if (k != out) face[static_cast<std::size_t>(n++)] = corners[static_cast<std::size_t>(k)];
    std::uint32_t next = kOutside;
    for (std::uint32_t i = nodeCellStart_[face[0]]; i < nodeCellStart_[face[0] + 1] && next == kOutside;
         ++i) {
      const std::uint32_t other = nodeCells_[i];
      if (other == cell) continue;
      const auto& c = volume_.cells[other];
      const auto holds = [&](std::uint32_t node) { return std::find(c.begin(), c.end(), node) != c.end(); };
      if (holds(face[1]) && holds(face[2])) next = other;
    }
    if (next == kOutside) return false;
    cell = next;
  }
  return false;
}

CellPoint VolumeLocator::locate(const Vec3d& point, std::uint32_t hint) const {
  CellPoint found;
  if (hint != kOutside && hint < volume_.cells.size() &&
      (walk(point, hint, found) || locateInCell(point, hint, found)))
    return found;
  if (volume_.cells.empty()) return found;
  std::array<int, 3> bin{};
  for (int axis = 0; axis < 3; ++axis) {
    const double t = (point[axis] - bounds_.lower[axis]) / binSize_[axis];
    const int dim = dims_[static_cast<std::size_t>(axis)];
    // A point just outside the box by rounding still finds its cell in the edge bin.
    if (t < -1e-6 * dim || t > dim * (1 + 1e-6) || std::isnan(t)) return found;
    bin[static_cast<std::size_t>(axis)] = std::clamp(static_cast<int>(t), 0, dim - 1);
  }
  const std::size_t b = (static_cast<std::size_t>(bin[2]) * static_cast<std::size_t>(dims_[1]) +
                         static_cast<std::size_t>(bin[1])) *
                            static_cast<std::size_t>(dims_[0]) +
                        static_cast<std::size_t>(bin[0]);
  for (std::uint32_t i = binStart_[b]; i < binStart_[b + 1]; ++i)
    if (locateInCell(point, binCells_[i], found)) return found;
  return CellPoint{};
}

void VolumeLocator::interpolate(const VolumeField& field, const CellPoint& at, float* out) const {
  const auto components = static_cast<std::size_t>(field.components);
  if (field.at == FieldAt::kNode && *std::max_element(at.points.begin(), at.points.end()) < kCellCentre) {
    // Node data on four corners (every tetrahedron, the pyramids' halves): no centre to make.
    const auto& corners = volume_.cells[at.cell];
    for (std::size_t c = 0; c < components; ++c) {
      double sum = 0;
      for (std::size_t k = 0; k < 4; ++k)
        sum += at.weights[k] * field.values[corners[at.points[k]] * components + c];
      out[c] = static_cast<float>(sum);
    }
    return;
  }
  std::array<float, (kMaxCellCorners + 1) * 9> values{};
  cellPointValues(volume_, field, at.cell, values.data());
  for (std::size_t c = 0; c < components; ++c) {
    double sum = 0;
    for (int k = 0; k < 4; ++k)
      sum += at.weights[static_cast<std::size_t>(k)] *
             values[at.points[static_cast<std::size_t>(k)] * components + c];
    out[c] = static_cast<float>(sum);
  }
}

}  // namespace lancer
