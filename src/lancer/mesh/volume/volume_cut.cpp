#include "lancer/mesh/volume/volume_cut.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lancer/mesh/volume/cell_tetrahedra.hpp"
#include "lancer/mesh/volume/volume_locator.hpp"

namespace lancer {
namespace {

constexpr std::uint64_t kEmptyKey = std::numeric_limits<std::uint64_t>::max();

// Cut vertices by the segment they lie on (its two end points as 32-bit ids), so that the cells on
// both sides of a face make one vertex: open addressing, grown at half full.
class SegmentVertices {
 public:
  std::uint32_t find(std::uint64_t key) const {
    if (keys_.empty()) return kNoVertex;
    for (std::size_t slot = mix(key) & mask_;; slot = (slot + 1) & mask_) {
      if (keys_[slot] == key) return values_[slot];
      if (keys_[slot] == kEmptyKey) return kNoVertex;
    }
  }
  void insert(std::uint64_t key, std::uint32_t value) {
    if ((count_ + 1) * 2 > keys_.size()) grow();
    std::size_t slot = mix(key) & mask_;
    while (keys_[slot] != kEmptyKey) slot = (slot + 1) & mask_;
    keys_[slot] = key;
    values_[slot] = value;
    ++count_;
  }

 private:
  static std::size_t mix(std::uint64_t key) {
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdULL;
    key ^= key >> 33;
    return static_cast<std::size_t>(key);
  }
  void grow() {
    std::vector<std::uint64_t> keys = std::move(keys_);
    std::vector<std::uint32_t> values = std::move(values_);
    const std::size_t size = std::max<std::size_t>(1024, keys.size() * 2);
    keys_.assign(size, kEmptyKey);
    values_.assign(size, 0);
    mask_ = size - 1;
    count_ = 0;
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (keys[i] != kEmptyKey) insert(keys[i], values[i]);
  }
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> values_;
  std::size_t mask_ = 0;
  std::size_t count_ = 0;
};

struct CellGeometry {
  std::array<Vec3d, kMaxCellCorners + 1> point;  // corners, then the centre
};

CellGeometry cellGeometry(const VolumeMesh& volume, std::uint32_t cell) {
  CellGeometry geometry;
  const int corners = cellCornerCount(volume.shapes[cell]);
  Vec3d sum{};
  for (int k = 0; k < corners; ++k) {
    geometry.point[static_cast<std::size_t>(k)] =
        toDouble(volume.nodes[volume.cells[cell][static_cast<std::size_t>(k)]]);
    sum = sum + geometry.point[static_cast<std::size_t>(k)];
  }
  geometry.point[kCellCentre] = sum * (1.0 / corners);
  return geometry;
}

class CutBuilder {
 public:
  CutBuilder(const VolumeMesh& volume, bool continuous) : volume_(volume), continuous_(continuous) {
    cut_.surface.origin = volume.origin;
  }

  void addCell(std::uint32_t cell, const float* level, float value) {
    const CellTetrahedra split = cellTetrahedra(volume_.shapes[cell], volume_.cells[cell]);
    const CellGeometry geometry = cellGeometry(volume_, cell);
    for (int t = 0; t < split.count; ++t)
      addTetrahedron(cell, split.tetrahedra[static_cast<std::size_t>(t)], level, value, geometry);
  }

  VolumeCut finish() { return std::move(cut_); }

 private:
  // A point's id, the same in every cell for a corner (its node) when the function is continuous.
  std::uint32_t pointId(std::uint32_t cell, std::uint8_t point) const {
    if (point == kCellCentre || !continuous_)
      return static_cast<std::uint32_t>(volume_.nodes.size()) + cell * (kMaxCellCorners + 1) + point;
    return volume_.cells[cell][point];
  }

  std::uint32_t vertexOn(std::uint32_t cell, std::uint8_t a, std::uint8_t b, const float* level, float value,
                         const CellGeometry& geometry, CutPoint& corner) {
    std::uint32_t idA = pointId(cell, a), idB = pointId(cell, b);
    // The segment in one direction whichever cell meets it, so both compute the same point.
    if (idA > idB) std::swap(a, b), std::swap(idA, idB);
    float t = (value - level[a]) / (level[b] - level[a]);
    // A cut through a node (a slice through a plane of nodes) is that node, whichever segment
    // reaches it: one vertex, shared by every triangle around it.
    if (level[a] == value) t = 0, idB = idA;
    if (level[b] == value) t = 1, idA = idB;
    corner = CutPoint{cell, a, b, t};
    const std::uint64_t key = (std::uint64_t{idA} << 32) | idB;
    const std::uint32_t known = vertices_.find(key);
    if (known != kNoVertex) return known;
    const Vec3d& pa = geometry.point[a];
    const Vec3d& pb = geometry.point[b];
    const auto index = static_cast<std::uint32_t>(cut_.surface.positions.size());
    cut_.surface.positions.push_back(toFloat(t == 0   ? pa
                                             : t == 1 ? pb
                                                      : pa + (pb - pa) * static_cast<double>(t)));
    cut_.vertexPoint.push_back(corner);
    vertices_.insert(key, index);
    return index;
  }

  void addTriangle(std::uint32_t cell, std::array<std::uint32_t, 3> vertex, std::array<CutPoint, 3> corner,
                   const Vec3d& towardsHigher) {
    if (vertex[0] == vertex[1] || vertex[1] == vertex[2] || vertex[0] == vertex[2]) return;
    const Vec3d p0 = toDouble(cut_.surface.positions[vertex[0]]);
    const Vec3d normal = cross(toDouble(cut_.surface.positions[vertex[1]]) - p0,
                               toDouble(cut_.surface.positions[vertex[2]]) - p0);
    // Slivers (a cut through nodes makes triangles of next to no width along the elements' faces)
    // cover nothing and are dropped.
    const double longest = std::max(
        {dot(toDouble(cut_.surface.positions[vertex[1]]) - p0,
             toDouble(cut_.surface.positions[vertex[1]]) - p0),
         dot(toDouble(cut_.surface.positions[vertex[2]]) - p0,
             toDouble(cut_.surface.positions[vertex[2]]) - p0),
         dot(toDouble(cut_.surface.positions[vertex[2]]) - toDouble(cut_.surface.positions[vertex[1]]),
             toDouble(cut_.surface.positions[vertex[2]]) - toDouble(cut_.surface.positions[vertex[1]]))});
    if (!(dot(normal, normal) > 1e-16 * longest * longest)) return;
    if (dot(normal, towardsHigher) < 0) std::swap(vertex[1], vertex[2]), std::swap(corner[1], corner[2]);
    cut_.surface.faces.push_back(MeshFace{{vertex[0], vertex[1], vertex[2], kNoVertex}});
    cut_.surface.facePhysicalTag.push_back(volume_.cellPhysicalTag[cell]);
    cut_.surface.faceEntityTag.push_back(volume_.cellEntityTag[cell]);
    cut_.surface.faceEdgeMask.push_back(0);
    cut_.faceCell.push_back(cell);
    cut_.faceCorners.push_back(corner);
  }

  void addTetrahedron(std::uint32_t cell, const std::array<std::uint8_t, 4>& tet, const float* level,
                      float value, const CellGeometry& geometry) {
    std::array<std::uint8_t, 4> above{}, below{};
    int aboveCount = 0, belowCount = 0;
    for (const std::uint8_t p : tet) (level[p] >= value ? above[aboveCount++] : below[belowCount++]) = p;
    if (aboveCount == 0 || belowCount == 0) return;
    // The level's gradient on the tetrahedron points from the points below to those above.
    Vec3d towardsHigher{};
    for (int i = 0; i < aboveCount; ++i)
      towardsHigher = towardsHigher + geometry.point[above[static_cast<std::size_t>(i)]];
    towardsHigher = towardsHigher * (1.0 / aboveCount);
    Vec3d lowMean{};
    for (int i = 0; i < belowCount; ++i)
      lowMean = lowMean + geometry.point[below[static_cast<std::size_t>(i)]];
    towardsHigher = towardsHigher - lowMean * (1.0 / belowCount);
    std::array<CutPoint, 4> corner{};
    const auto on = [&](std::uint8_t a, std::uint8_t b, CutPoint& point) {
      return vertexOn(cell, a, b, level, value, geometry, point);
    };
    if (aboveCount == 1 || belowCount == 1) {
      const std::uint8_t apex = aboveCount == 1 ? above[0] : below[0];
      const std::array<std::uint8_t, 4>& others = aboveCount == 1 ? below : above;
      const std::array<std::uint32_t, 3> vertex{
          on(apex, others[0], corner[0]), on(apex, others[1], corner[1]), on(apex, others[2], corner[2])};
      addTriangle(cell, vertex, {corner[0], corner[1], corner[2]}, towardsHigher);
      return;
    }
    // Two above (a, b), two below (c, d): the quad ac, ad, bd, bc.
    const std::array<std::uint32_t, 4> quad{
        on(above[0], below[0], corner[0]), on(above[0], below[1], corner[1]),
        on(above[1], below[1], corner[2]), on(above[1], below[0], corner[3])};
    addTriangle(cell, {quad[0], quad[1], quad[2]}, {corner[0], corner[1], corner[2]}, towardsHigher);
    addTriangle(cell, {quad[0], quad[2], quad[3]}, {corner[0], corner[2], corner[3]}, towardsHigher);
  }

  const VolumeMesh& volume_;
  bool continuous_;
  VolumeCut cut_;
  SegmentVertices vertices_;
};

}  // namespace

VolumeCut cutVolume(const VolumeMesh& volume, const CellLevels& levels, float level, bool continuous) {
  CutBuilder builder(volume, continuous);
  std::array<float, kMaxCellCorners + 1> values{};
  for (std::uint32_t cell = 0; cell < volume.cells.size(); ++cell) {
    levels(cell, values.data());
    const int corners = cellCornerCount(volume.shapes[cell]);
    float low = values[kCellCentre], high = values[kCellCentre];
    bool finite = std::isfinite(values[kCellCentre]);
    for (int k = 0; k < corners; ++k) {
      low = std::min(low, values[static_cast<std::size_t>(k)]);
      high = std::max(high, values[static_cast<std::size_t>(k)]);
      finite = finite && std::isfinite(values[static_cast<std::size_t>(k)]);
    }
    // A cell the level does not cross, or one with a missing value (NaN), adds nothing.
    if (!finite || level < low || level > high) continue;
    builder.addCell(cell, values.data(), level);
  }
  VolumeCut cut = builder.finish();
  cut.surface.source.path = "cut";
  return cut;
}

VolumeCut sliceVolume(const VolumeMesh& volume, const Vec3d& point, const Vec3d& normal) {
  const Vec3d unit = normalize(normal);
  const CellLevels distance = [&](std::uint32_t cell, float* out) {
    const int corners = cellCornerCount(volume.shapes[cell]);
    double sum = 0;
    for (int k = 0; k < corners; ++k) {
      const double d =
          dot(toDouble(volume.nodes[volume.cells[cell][static_cast<std::size_t>(k)]]) - point, unit);
      out[k] = static_cast<float>(d);
      sum += d;
    }
    out[kCellCentre] = static_cast<float>(sum / corners);
  };
  VolumeCut cut = cutVolume(volume, distance, 0.0F, true);
  // A plane across an axis is made exactly flat: rounding leaves its points a few ulps off it, and a
  // surface that thin but not flat is far slower to trace than either a flat or a thick one.
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(unit[axis]) != 1.0) continue;
    const auto on = static_cast<float>(point[axis]);
    for (Vec3& position : cut.surface.positions) position[axis] = on;
  }
  return cut;
}

MeshField cutField(const VolumeCut& cut, const VolumeMesh& volume, const VolumeField& field) {
  MeshField out;
  out.name = field.name;
  out.at = field.at;
  out.components = field.components;
  out.step = field.step;
  out.time = field.time;
  const auto components = static_cast<std::size_t>(field.components);
  std::vector<float> cellValues((kMaxCellCorners + 1) * components);
  const auto valueAt = [&](const CutPoint& point, std::size_t c) {
    const float a = cellValues[point.a * components + c];
    const float b = cellValues[point.b * components + c];
    return a + (b - a) * point.t;
  };
  switch (field.at) {
    case FieldAt::kNode:
      out.values.resize(cut.vertexPoint.size() * components);
      for (std::size_t v = 0; v < cut.vertexPoint.size(); ++v) {
        cellPointValues(volume, field, cut.vertexPoint[v].cell, cellValues.data());
        for (std::size_t c = 0; c < components; ++c)
          out.values[v * components + c] = valueAt(cut.vertexPoint[v], c);
      }
      break;
    case FieldAt::kElement:
      out.values.resize(cut.faceCell.size() * components);
      for (std::size_t f = 0; f < cut.faceCell.size(); ++f)
        for (std::size_t c = 0; c < components; ++c)
          out.values[f * components + c] = field.values[cut.faceCell[f] * components + c];
      break;
    case FieldAt::kCorner:
      out.values.assign(cut.faceCell.size() * kCornerSlots * components,
                        std::numeric_limits<float>::quiet_NaN());
      for (std::size_t f = 0; f < cut.faceCell.size(); ++f) {
        cellPointValues(volume, field, cut.faceCell[f], cellValues.data());
        const MeshFace& face = cut.surface.faces[f];
        for (int k = 0; k < 3; ++k) {
          const auto slot = static_cast<std::size_t>(cornerSlot(face, k));
          for (std::size_t c = 0; c < components; ++c)
            out.values[(f * kCornerSlots + slot) * components + c] =
                valueAt(cut.faceCorners[f][static_cast<std::size_t>(k)], c);
        }
      }
      break;
  }
  return out;
}

}  // namespace lancer
