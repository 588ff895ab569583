// Small scenes built in code for the renderer's analytic tests, where the geometry is the oracle
// (planes and squares at known places) rather than a mesh file.
#pragma once

#include <vector>

#include "lancer/accel/accelerator.hpp"
#include "lancer/image/image.hpp"
#include "lancer/mesh/mesh.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer::test {

// An axis-aligned square in the plane z = height, facing +z, from (x0, y0) to (x1, y1).
Mesh squareMesh(float x0, float y0, float x1, float y1, float height, std::int32_t physicalTag = 1);

// Builds the scene from in-memory meshes (one per description.meshes entry).
Scene sceneFromMeshes(const SceneDescription& description, std::vector<Mesh> meshes);

// A material that shows only ambient light: under ambient 1 a pixel's value is exactly its ka.
Material ambientOnlyMaterial(const char* name, Vec3 ka);

// Renders with the given accelerator kind and thread count.
Image renderScene(const SceneDescription& description, const Scene& scene, AccelKind accel = AccelKind::KdTreeSah,
                  int threads = 0);
// Reads the description's meshes, builds its scene and renders it (kd-tree, all cores).
Image renderScene(const SceneDescription& description);

}  // namespace lancer::test
