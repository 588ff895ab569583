// The meshes of a scene as they join it (scene_builder.cpp's first step): each mesh's colours at the
// step shown (meshes colouring by one field share one range), its warp, and undeformed copies.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/results/color_by.hpp"
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
  std::size_t meshIndex = 0;       // of its mesh in the description
  bool undeformedCopy = false;
  std::uint64_t collapsedFaces = 0;  // dropped by the warp
};

// Each mesh's colours at description.when, from sources[i]'s views for description.meshes[i]:
// meshes colouring by one field and map without a range of their own share the union of their
// ranges, so that a colour (and one legend) means one value on all of them.
struct SceneColorings {
  std::vector<std::optional<ColorBy>> specs;
  std::vector<std::optional<FieldColoring>> colorings;
};
SceneColorings resolveSceneColorings(const SceneDescription& description,
                                     const std::vector<const Mesh*>& sources);

// A mesh drawn as the backdrop of what matters (the shape before a warp, the skin around a slice):
// a faint glass-like copy (ghost), or only its feature edges on a surface that lets everything
// through; neither coloured, warped nor annotated, but for arrows through the volume inside it. Its
// material is appended to `materials`.
MeshInstance backdropInstance(const MeshInstance& instance, bool ghost, std::vector<Material>& materials);

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
