#include "lancer/mesh/mesh.hpp"

namespace lancer {

std::string Mesh::physicalName(std::int32_t tag) const {
  const PhysicalGroup* best = nullptr;
  for (const PhysicalGroup& group : physicalGroups) {
    if (group.tag != tag) continue;
    // A tag can be reused across dimensions; the surface (2D) group is the one faces belong to.
    if (best == nullptr || group.dimension == 2) best = &group;
  }
  return best ? best->name : std::string();
}

const std::vector<std::int32_t>* Mesh::findMorePhysicalTags(std::int32_t entity, std::int32_t first) const {
  // A handful of entries (one per entity with several groups): a linear scan is the fastest lookup.
  for (const ExtraPhysicalGroups& extra : extraPhysicalGroups)
    if (extra.entity == entity && extra.first == first) return &extra.more;
  return nullptr;
}

Aabb faceBounds(const Mesh& mesh) {
  Aabb box;
  for (const MeshFace& face : mesh.faces) {
    for (int c = 0; c < face.cornerCount(); ++c) box.extend(mesh.positions[face.vertex[c]]);
  }
  return box;
}

}  // namespace lancer
