#include "lancer/mesh/surface_formats/surface_mesh.hpp"

#include <cstring>

#include "lancer/mesh/mesh_from_elements.hpp"
#include "lancer/util/stopwatch.hpp"

namespace lancer {

SurfaceGroup& SurfaceData::group(std::string_view name) {
  const auto [at, added] = groupIndex_.try_emplace(std::string(name), groups.size());
  if (added) groups.push_back(SurfaceGroup{std::string(name), {}, {}});
  return groups[at->second];
}

Mesh meshFromSurface(const SurfaceData& data, MeshSourceInfo source) {
  const Stopwatch stopwatch;
  std::vector<ElementBlock> blocks;
  std::vector<PhysicalGroup> names;
  std::int32_t tag = 0;
  for (const SurfaceGroup& group : data.groups) {
    if (group.faceCount() == 0) continue;
    ++tag;
    if (!group.name.empty()) names.push_back(PhysicalGroup{2, tag, group.name});
    if (!group.triangles.empty()) blocks.push_back(ElementBlock{2, 2, tag, tag, group.triangles, {}});
    if (!group.quads.empty()) blocks.push_back(ElementBlock{3, 2, tag, tag, group.quads, {}});
  }
  std::vector<NodeFieldInput> fields;
  for (const SurfaceVertexField& field : data.fields)
    fields.push_back(NodeFieldInput{field.name, 1, field.values, 0, 0});
  Mesh mesh = meshFromElements(data.points, blocks, std::move(names), source.path, fields);
  const MeshSourceInfo assembled = std::move(mesh.source);
  mesh.source = std::move(source);
  mesh.source.nodeCount = data.points.size();
  mesh.source.elementsByType = assembled.elementsByType;
  mesh.source.degenerateFacesDropped = assembled.degenerateFacesDropped;
  mesh.source.warnings.insert(mesh.source.warnings.end(), assembled.warnings.begin(),
                              assembled.warnings.end());
  mesh.source.loadSeconds = stopwatch.seconds();
  return mesh;
}

namespace {

struct PointKey {
  Vec3d p;
  bool operator==(const PointKey& other) const {
    return p.x == other.p.x && p.y == other.p.y && p.z == other.p.z;
  }
};

struct PointKeyHash {
  std::size_t operator()(const PointKey& key) const {
    // -0.0 and 0.0 are the same point: hash their sum with +0.0 so both hash alike.
    std::uint64_t bits[3];
    const double values[3] = {key.p.x + 0.0, key.p.y + 0.0, key.p.z + 0.0};
    std::memcpy(bits, values, sizeof bits);
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (const std::uint64_t b : bits) h = (h ^ b) * 0x100000001B3ull, h ^= h >> 29;
    return static_cast<std::size_t>(h);
  }
};

}  // namespace

std::vector<std::uint32_t> weldPoints(std::vector<Vec3d>& points) {
  std::unordered_map<PointKey, std::uint32_t, PointKeyHash> index;
  index.reserve(points.size() / 2);
  std::vector<std::uint32_t> corners(points.size());
  std::size_t distinct = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto [at, added] = index.try_emplace(PointKey{points[i]}, static_cast<std::uint32_t>(distinct));
    if (added) points[distinct++] = points[i];
    corners[i] = at->second;
  }
  points.resize(distinct);
  points.shrink_to_fit();
  return corners;
}

}  // namespace lancer
