// Small scenes built in code for the renderer's analytic tests, where the geometry is the oracle
// (planes and squares at known places) rather than a mesh file.
#pragma once

#include <functional>
#include <initializer_list>
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

// An orthographic view of width x height pixels from `position` towards `lookAt`, `viewHeight`
// world units tall, primary rays only (maxDepth 0): the camera of the analytic render tests, where
// the world point behind each pixel is known exactly. Lights, materials and meshes are the caller's.
SceneDescription orthographicView(int width, int height, Vec3d position, Vec3d lookAt, double viewHeight,
                                  Vec3d up = {0, 1, 0});

// orthographicView straight down -z from (0, 0, 5) onto the origin: +x to the right, +y up.
SceneDescription topDownView(int width, int height, double viewHeight);

// `view` lit like the cut-view tests: flat shading over a blue background, ambient 0.2 and one
// unattenuated light of 0.7 at `light`.
SceneDescription flatLitOnBlue(SceneDescription view, Vec3d light);

// A material that shows only ambient light: under ambient 1 a pixel's value is exactly its ka.
Material ambientOnlyMaterial(const char* name, Vec3 ka);

// A material without specular highlights, so that flat shading gives one colour per face.
Material matteMaterial(const char* name, Vec3 ka, Vec3 kd);

// Renders with the given accelerator kind and thread count.
Image renderScene(const SceneDescription& description, const Scene& scene, AccelKind accel = kDefaultAccel,
                  int threads = 0, RenderStats* stats = nullptr);
// Builds the scene from in-memory meshes (one per description.meshes entry) and renders it.
Image renderMeshes(const SceneDescription& description, std::vector<Mesh> meshes,
                   AccelKind accel = kDefaultAccel, int threads = 0);
// Reads the description's meshes, builds its scene and renders it (default accelerator, all cores).
Image renderScene(const SceneDescription& description);

// For the tests that guard a golden: renders `description`, then each of `changes` applied to it (a
// lost cap, a volume in another material), and adds a gtest failure for each change whose picture
// the golden's PSNR floor (kRenderGoldenMinPsnrDb) would not tell from the unchanged one.
void expectEachChangeBelowGoldenFloor(const SceneDescription& description,
                                      std::initializer_list<std::function<void(SceneDescription&)>> changes);

}  // namespace lancer::test
