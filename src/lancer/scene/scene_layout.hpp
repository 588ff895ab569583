// Where each mesh of a built scene lies in the scene's arrays, and what its geometry was derived
// with: what an animation over warped steps needs to write the next step's scene over this one
// (scene_update.hpp) instead of building it beside the accelerator.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "lancer/mesh/shell_orientation.hpp"
#include "lancer/mesh/vertex_normals.hpp"

namespace lancer {

// One mesh as it joined the scene (SceneEntry): a mesh of the description, its undeformed copy, or
// an annotation's mesh (arrows).
struct SceneEntryLayout {
  std::size_t meshIndex = 0;  // into the description's meshes (annotations: past the meshes read)
  bool undeformedCopy = false;
  std::uint32_t vertexBase = 0, vertexCount = 0;
  std::uint32_t faceBase = 0, faceCount = 0;
  std::uint32_t normalBase = 0;
  std::uint64_t collapsedFaces = 0;  // dropped by its warp
  // Interface faces reversed by the orientation: their physical tag is the mesh's outer one.
  std::vector<std::uint32_t> reversedInterfaces;
  OrientedShells shells;
  CornerNormalWalks walks;
  bool featureEdges = false;  // draws feature edges, which depend on its shape
};

struct SceneLayout {
  std::vector<SceneEntryLayout> entries;
};

}  // namespace lancer
