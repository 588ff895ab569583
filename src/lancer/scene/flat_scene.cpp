#include "lancer/scene/flat_scene.hpp"

#include "lancer/scene/camera_placement.hpp"
#include "lancer/scene/results/warp.hpp"

namespace lancer {

bool applyFlatSceneDefaults(SceneDescription& description, const std::vector<Mesh>& meshes,
                            const FlatSceneChoices& choices) {
  CameraSettings& camera = description.camera;
  if (camera.viewChosen || camera.position || camera.gmshView || meshes.empty()) return false;
  if (!frameFlatScene(camera, warpedWorldBounds(description, meshes))) return false;
  const bool lightsAsked = choices.look || (!description.lightsFollowCamera &&
                                            (!description.lights.empty() || description.environment));
  if (lightsAsked || choices.shading) return true;
  for (MeshInstance& mesh : description.meshes)
    if (mesh.colorBy && mesh.colorBy->paintsSurface && !mesh.shading) mesh.shading = ShadingMode::Unlit;
  return true;
}

}  // namespace lancer
