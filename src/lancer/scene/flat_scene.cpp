#include "lancer/scene/flat_scene.hpp"

#include <algorithm>

#include "lancer/scene/camera_placement.hpp"
#include "lancer/scene/results/warp.hpp"

namespace lancer {
namespace {

// The bounds the flat test sees: every mesh's but those of field lines lying on a 2D mesh (the
// others are copied then, which only scenes with such lines pay).
Aabbd flatTestBounds(const SceneDescription& description, const std::vector<Mesh>& meshes) {
  const auto onPlane = [](const MeshInstance& instance) { return instance.liesOnPlane; };
  if (std::none_of(description.meshes.begin(), description.meshes.end(), onPlane))
    return warpedWorldBounds(description, meshes);
  SceneDescription rest = description;
  rest.meshes.clear();
  std::vector<Mesh> restMeshes;
  for (std::size_t i = 0; i < meshes.size() && i < description.meshes.size(); ++i) {
    if (onPlane(description.meshes[i])) continue;
    rest.meshes.push_back(description.meshes[i]);
    restMeshes.push_back(meshes[i]);
  }
  return warpedWorldBounds(rest, restMeshes);
}

}  // namespace

bool applyFlatSceneDefaults(SceneDescription& description, const std::vector<Mesh>& meshes,
                            const FlatSceneChoices& choices) {
  CameraSettings& camera = description.camera;
  if (camera.viewChosen || camera.position || camera.gmshView || meshes.empty()) return false;
  if (!frameFlatScene(camera, flatTestBounds(description, meshes))) return false;
  const bool lightsAsked = choices.look || (!description.lightsFollowCamera &&
                                            (!description.lights.empty() || description.environment));
  if (lightsAsked || choices.shading) return true;
  for (MeshInstance& mesh : description.meshes)
    if (mesh.colorBy && mesh.colorBy->paintsSurface && !mesh.shading) mesh.shading = ShadingMode::Unlit;
  return true;
}

}  // namespace lancer
