// The meshes of a scene as they join it (scene_builder.cpp's first step): each mesh's colours at the
// step shown (meshes colouring by one field share one range), its warp, and undeformed copies.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/color_by.hpp"
#include "lancer/scene/scene_description.hpp"

namespace lancer {

// A mesh as it joins the scene: its instance (the scene's, or one made for an undeformed copy), its
// geometry (warped when asked) and its colours at the step shown.
struct SceneEntry {
  MeshInstance instance;
  Mesh mesh;
  std::optional<FieldColoring> coloring;
  std::optional<ColorBy> colorBy;  // what `coloring` was resolved from, its range shared (legends)
  const Mesh* fields = nullptr;    // the mesh's views when `mesh` is a copy without them
};

// Everything of a mesh but its fields: what a step's scene is built from (the fields stay with the
// mesh as read, which holds every step).
Mesh geometryOf(const Mesh& mesh);

// The meshes at description.when: colours resolved, warps applied (undeformed copies added after
// their mesh, with their materials appended to `materials`). `fields[i]` holds mesh i's views; null:
// mesh i itself (read for this scene alone). Warnings (collapsed faces) are appended to `warnings`.
std::vector<SceneEntry> sceneEntries(const SceneDescription& description, std::vector<Mesh> meshes,
                                     const std::vector<const Mesh*>& fields, std::vector<Material>& materials,
                                     std::vector<std::string>& warnings);

}  // namespace lancer
