#include "lancer/mesh/mesh_stats.hpp"

#include <algorithm>
#include <utility>

#include "lancer/mesh/face_geometry.hpp"
#include "lancer/mesh/face_shells.hpp"
#include "lancer/mesh/shell_nesting.hpp"

namespace lancer {

MeshStats computeMeshStats(const Mesh& mesh) {
  MeshStats stats;
  const std::size_t faceCount = mesh.faces.size();
  for (std::size_t f = 0; f < faceCount; ++f) {
    const MeshFace& face = mesh.faces[f];
    face.isQuad() ? ++stats.quads : ++stats.triangles;
    stats.area += faceArea(mesh.positions, face);
    ++stats.facesByPhysicalTag[mesh.facePhysicalTag[f]];
    if (const std::vector<std::int32_t>* more = mesh.morePhysicalTags(f))
      for (const std::int32_t tag : *more) ++stats.facesByPhysicalTag[tag];
    if (mesh.volumeSides.isInterface(f)) {
      const std::int32_t inner = mesh.facePhysicalTag[f], outer = mesh.volumeSides.outerPhysicalTag[f];
      if (outer != inner) ++stats.facesByPhysicalTag[outer];
      ++stats.interfaceFacesByPhysicalTag[inner];
      if (outer != inner) ++stats.interfaceFacesByPhysicalTag[outer];
      const std::int64_t a = inner != 0 ? inner : -std::int64_t{mesh.faceEntityTag[f]};
      const std::int64_t b = outer != 0 ? outer : -std::int64_t{mesh.volumeSides.outerEntityTag[f]};
      ++stats.interfaces[{std::min(a, b), std::max(a, b)}];
    }
    for (int c = 0; c < face.cornerCount(); ++c) stats.worldBounds.extend(mesh.worldPosition(face.vertex[c]));
  }
  const FaceShells faceShells = findFaceShells(mesh.faces);
  std::vector<MeshShell> shells(faceShells.shellCount());
  for (std::size_t f = 0; f < faceCount; ++f) {
    MeshShell& shell = shells[faceShells.shellOfFace[f]];
    ++shell.faceCount;
    shell.area += faceArea(mesh.positions, mesh.faces[f]);
    shell.signedVolume += sixfoldConeVolume(mesh.positions, mesh.faces[f]) / 6.0;
  }
  std::vector<std::uint8_t> solid(shells.size(), 0);
  for (std::size_t s = 0; s < shells.size(); ++s) {
    shells[s].closed = faceShells.closed[s] != 0;
    shells[s].consistentlyOriented = faceShells.consistent[s] != 0;
    solid[s] = shells[s].closed && shells[s].consistentlyOriented;
  }
  const std::vector<std::uint8_t> cavity =
      findCavityShells(mesh.positions, mesh.faces, faceShells, mesh.facePhysicalTag, solid);
  for (std::size_t f = 0; f < faceCount; ++f)
    if (mesh.volumeSides.isInterface(f)) shells[faceShells.shellOfFace[f]].interface = true;
  for (std::size_t s = 0; s < shells.size(); ++s) shells[s].cavity = cavity[s] != 0 && !shells[s].interface;
  std::stable_sort(shells.begin(), shells.end(),
                   [](const MeshShell& a, const MeshShell& b) { return a.faceCount > b.faceCount; });
  stats.shells = std::move(shells);
  return stats;
}

}  // namespace lancer
