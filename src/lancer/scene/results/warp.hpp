// Deformed shapes: `warp = { field = "displacement", factor = 2.0 }` on a [[mesh]] moves every node by
// factor times its vector of the step shown, before the mesh is placed in the scene, so normals,
// shells, edges, cut views and caps are those of the deformed shape. Faces the warp collapses (zero
// area, or a corner at infinity) are dropped and counted, never drawn as NaN.
#pragma once

#include <cstdint>
#include <vector>

#include "lancer/math/aabb.hpp"
#include "lancer/mesh/field_steps.hpp"
#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/scene_description.hpp"

namespace lancer {

struct WarpReport {
  std::uint64_t collapsedFaces = 0;  // dropped: degenerate once deformed
};

// The view warp.field of `fields` at `when`, checked as warpMesh says, for a mesh of vertexCount
// vertices (not copied).
ViewValues warpDisplacement(const Mesh& fields, const WarpSettings& warp, const StepSelection& when,
                            std::size_t vertexCount);

// Moves `mesh`'s vertices by warp.factor times the view warp.field of `fields` (the mesh as read,
// which holds every step) at `when`, then drops the faces that collapsed; `perFaceValues`, when
// given, holds values per face or per face corner slot (an element or element-node field's colours)
// and loses the same entries. Throws InputError at warp.where naming the file, view and step for a
// view that is missing, not a vector of 3 components at nodes or element nodes, without the step, or
// without a value for some vertex.
WarpReport warpMesh(Mesh& mesh, const Mesh& fields, const WarpSettings& warp, const StepSelection& when,
                    std::vector<float>* perFaceValues = nullptr);

// The world bounds of the meshes (meshes[i] placed by description.meshes[i]) at description.when,
// warped, without building the scene: what an animation over steps frames its camera on.
Aabbd warpedWorldBounds(const SceneDescription& description, const std::vector<Mesh>& meshes);

// Removes the faces marked in `removed` from every per-face array of `mesh` (and `perFaceValues`).
void removeMeshFaces(Mesh& mesh, const std::vector<std::uint8_t>& removed, std::vector<float>* perFaceValues);

}  // namespace lancer
