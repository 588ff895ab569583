#include "lancer/scene/quick_look.hpp"

#include <algorithm>
#include <set>

#include "lancer/scene/camera_placement.hpp"

namespace lancer {
namespace {

// Okabe & Ito's colour-blind-safe palette (2008), without black, then a few muted extras.
constexpr Vec3 kPalette[] = {
    {0.00f, 0.45f, 0.70f},  // blue
    {0.90f, 0.62f, 0.00f},  // orange
    {0.00f, 0.62f, 0.45f},  // bluish green
    {0.80f, 0.47f, 0.65f},  // reddish purple
    {0.34f, 0.71f, 0.91f},  // sky blue
    {0.84f, 0.37f, 0.00f},  // vermillion
    {0.94f, 0.89f, 0.26f},  // yellow
    {0.55f, 0.55f, 0.60f},  // grey
};
constexpr Vec3 kUngroupedColour{0.62f, 0.66f, 0.72f};  // light steel, for meshes without groups

Material paintedMaterial(const std::string& name, const Vec3& colour) {
  Material material;
  material.name = name;
  material.ka = colour;
  material.kd = colour * 0.85f;
  material.ks = {0.25f, 0.25f, 0.25f};
  material.shininess = 40;
  return material;
}

// The mesh's face bounds (faceBounds) in world space; the mesh's origin where it has no faces.
Aabbd worldBounds(const Mesh& mesh, const Aabb& bounds) {
  return bounds.empty() ? Aabbd{mesh.origin, mesh.origin}
                        : Aabbd{mesh.origin + toDouble(bounds.lower), mesh.origin + toDouble(bounds.upper)};
}

}  // namespace

SceneDescription quickLookScene(const std::string& meshPath, const Mesh& mesh, std::optional<UpAxis> up,
                                int threads) {
  SceneDescription scene;
  scene.path = meshPath;
  scene.render.shading = ShadingMode::Phong;
  scene.render.background = {0.96f, 0.96f, 0.97f};
  scene.ambient = {0.2f, 0.2f, 0.2f};
  scene.materials.push_back(paintedMaterial("default", kUngroupedColour));

  MeshInstance instance;
  instance.file = meshPath;
  instance.where.file = meshPath;
  instance.material = 0;
  instance.smoothAngleDegrees = 40;
  // Groups on the outside (faces that are not interfaces) are coloured as in a mesh without
  // interfaces, so a multi-material part looks the same from outside; groups met only inside it, on
  // interfaces (balls inside a block), take the next colours.
  std::set<std::int32_t> outside, inside;
  std::optional<std::int32_t> lastOutside;  // faces come in runs of one group: one look-up a run
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    if (!mesh.volumeSides.isInterface(f)) {
      if (mesh.facePhysicalTag[f] != lastOutside) outside.insert(*(lastOutside = mesh.facePhysicalTag[f]));
      continue;
    }
    inside.insert(mesh.facePhysicalTag[f]);
    inside.insert(mesh.volumeSides.outerPhysicalTag[f]);
  }
  for (std::int32_t tag : outside) inside.erase(tag);
  int colourIndex = 0;
  auto paint = [&](std::int32_t tag) {
    const std::string name = mesh.physicalName(tag);
    scene.materials.push_back(paintedMaterial(name.empty() ? std::to_string(tag) : name,
                                              kPalette[colourIndex++ % std::size(kPalette)]));
    instance.groupMaterials.push_back(
        {std::to_string(tag), static_cast<int>(scene.materials.size() - 1), instance.where});
  };
  // One group outside (or none) keeps the neutral colour; faces outside any group keep it too.
  for (std::int32_t tag : outside)
    if (tag != 0 && outside.size() > 1) paint(tag);
  for (std::int32_t tag : inside)
    if (tag != 0) paint(tag);
  scene.meshes.push_back(instance);

  // One pass for the up axis and the lights (placed again for another image size from these).
  const Aabb bounds = faceBoundsOnThreads(mesh, threads);
  scene.quickLookBounds = worldBounds(mesh, bounds);
  if (up) {
    applyUpAxis(scene.camera, *up);
  } else {
    const UpGuess guess = guessUpAxis(mesh, bounds, threads);
    scene.camera.up = guess.frame.up;
    scene.camera.viewFrom = guess.frame.toViewer;
  }
  scene.lightsFollowCamera = true;
  placeQuickLookLights(scene, mesh, threads);
  return scene;
}

void placeQuickLookLights(SceneDescription& scene, const Mesh& mesh, int threads) {
  if (!scene.quickLookBounds) scene.quickLookBounds = worldBounds(mesh, faceBoundsOnThreads(mesh, threads));
  const Aabbd world = *scene.quickLookBounds;
  const Vec3d centre = world.center();
  const double radius = std::max(0.5 * length(world.extent()), 1e-12);
  // A camera placed by the user (a position, a gmsh view) takes the lights along: its frame, its eye.
  const double aspect = static_cast<double>(scene.render.width) / scene.render.height;
  const CameraSettings camera = resolveGmshView(scene.camera, world, aspect);
  const Vec3d viewFrom =
      camera.position ? *camera.position - camera.lookAt.value_or(centre) : camera.viewFrom;
  // The camera's frame: screen right, up, and the front (towards the viewer's side of the model).
  const Vec3d up = normalize(camera.up);
  const Vec3d right = normalize(cross(-viewFrom, up));
  const Vec3d front = cross(right, up);
  scene.lights.clear();
  // The key: high on the left, in front, so the top, front and side faces of the 3/4 view read
  // apart; far enough to light the whole part evenly.
  PointLight key;
  key.position = centre + normalize(right * -0.5 + up * 1.8 + front * 0.9) * (6 * radius);
  key.intensity = {0.9f, 0.9f, 0.9f};
  scene.lights.push_back(key);
  // The fill sits at the eye: whatever the camera sees, it lights (the shadow ray retraces the view).
  PointLight fill;
  fill.position = camera.position.value_or(defaultCameraPosition(world, camera, aspect));
  fill.intensity = {0.5f, 0.5f, 0.52f};
  scene.lights.push_back(fill);
}

}  // namespace lancer
