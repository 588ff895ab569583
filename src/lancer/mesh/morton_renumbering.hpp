// A mesh's vertices and faces renumbered in Morton order of where they lie, once before a render
// prepares it: gmsh numbers nodes and elements in the order it meshed them, which scatters a face's
// neighbours and vertices over the arrays as meshes grow, and every pass that follows faces to
// their vertices and neighbours (shells, orientation, normals, the tree's build) then waits on memory.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

// Below this many faces the arrays a pass walks fit in the caches and the renumbering would cost
// more than it saves (bench/RESULTS.md, "Locality": measured at 100K, 1M and 4M triangles).
inline constexpr std::size_t kMortonRenumberingMinFaces = std::size_t(1) << 18;

// Which number each vertex and face had before: new number i was number original[i].
struct MeshRenumbering {
  std::shared_ptr<const std::vector<std::uint32_t>> originalVertex;
  std::shared_ptr<const std::vector<std::uint32_t>> originalFace;
};

// Vertices in Morton order of their positions, faces in Morton order of their centroids (on the
// same grid over the vertices' box; equal codes keep their order, so the result depends on the mesh
// alone, not on `threads`). Every per-vertex and per-face array follows: faces' corners, tags, edge
// masks, volume sides, and the fields of every step (node values by vertex, element values by face,
// element-node values by face and by corner slot, which follows the corners' new ranks); a step left
// in its file is put in the new order when it is read back. The faces keep their winding, groups and
// entities; nothing a user sees is numbered from the mesh after this (readers and `lancer info`
// number from the file).
MeshRenumbering renumberInMortonOrder(Mesh& mesh, int threads = 0);

// renumberInMortonOrder on each mesh of at least kMortonRenumberingMinFaces faces; how many it renumbered.
std::size_t renumberLargeMeshesInMortonOrder(std::vector<Mesh>& meshes, int threads = 0);

}  // namespace lancer
