#include "lancer/scene/looks.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace lancer {
namespace {

// A field's colours keep their map's saturation, as in ParaView and gmsh (no highlights on coloured
// data by default): under a look, light comes from the whole grey or blue surroundings, and a
// material's Phong lobe adds their colour to every coloured pixel (the mean HSV saturation of a
// coloured beam fell from 0.81 to 0.41 under the studio look). The materials of meshes whose surface
// shows a field lose their ks; one that other meshes use too is copied for them first.
void dropFieldHighlights(SceneDescription& description) {
  const std::size_t count = description.materials.size();
  std::vector<std::uint8_t> coloured(count, 0), plain(count, 0);
  const auto shows = [](const MeshInstance& mesh) { return mesh.colorBy && mesh.colorBy->paintsSurface; };
  for (const MeshInstance& mesh : description.meshes) {
    std::vector<std::uint8_t>& used = shows(mesh) ? coloured : plain;
    used[static_cast<std::size_t>(mesh.material)] = 1;
    for (const GroupMaterial& group : mesh.groupMaterials) used[static_cast<std::size_t>(group.material)] = 1;
  }
  std::vector<int> own(count);
  for (std::size_t m = 0; m < count; ++m) {
    own[m] = static_cast<int>(m);
    if (!coloured[m]) continue;
    if (plain[m]) {
      Material copy = description.materials[m];
      copy.name += " (field colours)";
      own[m] = static_cast<int>(description.materials.size());
      description.materials.push_back(copy);
    }
    description.materials[static_cast<std::size_t>(own[m])].ks = {0, 0, 0};
  }
  for (MeshInstance& mesh : description.meshes) {
    if (!shows(mesh)) continue;
    mesh.material = own[static_cast<std::size_t>(mesh.material)];
    for (GroupMaterial& group : mesh.groupMaterials)
      group.material = own[static_cast<std::size_t>(group.material)];
  }
}

}  // namespace

void applyLook(SceneDescription& description, Look look) {
  CameraSettings& camera = description.camera;
  // The camera's frame: screen right, up, and the front (towards the viewer's side of the model).
  const Vec3d viewFrom =
      camera.position && camera.lookAt ? *camera.position - *camera.lookAt : camera.viewFrom;
  const Vec3d up = normalize(camera.up);
  const Vec3d right = normalize(cross(-viewFrom, up));
  const Vec3d front = cross(right, up);
  const Vec3d keyDirection = normalize(right * -1.2 + up * 1.5 + front * 0.5);

  description.render.integrator = IntegratorKind::Path;
  description.render.samples = std::max(description.render.samples, 64);
  if (description.render.noise == 0) description.render.noise = 0.02f;
  description.ambient = {0, 0, 0};
  description.ambientSet = false;
  for (Material& material : description.materials) material.ka = {0, 0, 0};
  dropFieldHighlights(description);
  description.lights.clear();
  FloorSettings floor;
  floor.normal = up;
  description.floor = floor;

  PointLight key;
  key.type = LightType::Sun;
  key.direction = keyDirection;
  EnvironmentSettings sky;
  sky.kind = EnvironmentSettings::Kind::Gradient;
  switch (look) {
    case Look::Studio:  // a large soft box high on the left, a grey studio around
      key.angleDegrees = 20;
      key.intensity = {0.9f, 0.9f, 0.9f};
      sky.zenith = {0.45f, 0.45f, 0.47f};
      sky.horizon = {0.38f, 0.38f, 0.39f};
      sky.ground = {0.25f, 0.25f, 0.25f};
      break;
    case Look::Sky:  // an overcast blue sky, a faint sun
      key.angleDegrees = 10;
      key.intensity = {0.45f, 0.435f, 0.4f};
      sky.zenith = {0.45f, 0.6f, 0.9f};
      sky.horizon = {0.85f, 0.88f, 0.92f};
      sky.ground = {0.3f, 0.28f, 0.25f};
      break;
    case Look::Sun:  // a clear day: the sun's own half degree, a blue sky
      key.angleDegrees = 0.53;
      key.intensity = {1.0f, 0.96f, 0.9f};
      sky.zenith = {0.2f, 0.3f, 0.55f};
      sky.horizon = {0.45f, 0.5f, 0.6f};
      sky.ground = {0.2f, 0.19f, 0.17f};
      break;
  }
  description.lights.push_back(key);
  description.environment = sky;
}

}  // namespace lancer
