#include "support/test_scenes.hpp"

#include <gtest/gtest.h>

#include "support/golden.hpp"

namespace lancer::test {

Mesh squareMesh(float x0, float y0, float x1, float y1, float height, std::int32_t physicalTag) {
  Mesh mesh;
  mesh.positions = {{x0, y0, height}, {x1, y0, height}, {x1, y1, height}, {x0, y1, height}};
  mesh.faces = {MeshFace{{0, 1, 2, 3}}};
  mesh.facePhysicalTag = {physicalTag};
  mesh.faceEntityTag = {1};
  mesh.faceEdgeMask = {kAllEdges};
  return mesh;
}

SceneDescription orthographicView(int width, int height, Vec3d position, Vec3d lookAt, double viewHeight,
                                  Vec3d up) {
  SceneDescription d;
  d.render.width = width;
  d.render.height = height;
  d.render.maxDepth = 0;
  d.camera.projection = Projection::Orthographic;
  d.camera.position = position;
  d.camera.lookAt = lookAt;
  d.camera.up = up;
  d.camera.viewHeight = viewHeight;
  return d;
}

SceneDescription topDownView(int width, int height, double viewHeight) {
  return orthographicView(width, height, Vec3d{0, 0, 5}, Vec3d{0, 0, 0}, viewHeight);
}

SceneDescription flatLitOnBlue(SceneDescription view, Vec3d light) {
  view.render.shading = ShadingMode::Flat;
  view.render.background = {0, 0, 1};
  view.ambient = {0.2f, 0.2f, 0.2f};
  view.lights = {{light, {0.7f, 0.7f, 0.7f}, {1, 0, 0}}};
  return view;
}

Material ambientOnlyMaterial(const char* name, Vec3 ka) { return matteMaterial(name, ka, {0, 0, 0}); }

Material matteMaterial(const char* name, Vec3 ka, Vec3 kd) {
  Material m;
  m.name = name;
  m.ka = ka;
  m.kd = kd;
  m.ks = {0, 0, 0};
  return m;
}

Scene sceneFromMeshes(const SceneDescription& description, std::vector<Mesh> meshes) {
  return buildScene(description, std::move(meshes));
}

Image renderScene(const SceneDescription& description, const Scene& scene, AccelKind accel, int threads,
                  RenderStats* stats) {
  const Accelerator accelerator = Accelerator::build(scene.geometry.positions, scene.geometry.faces, accel);
  const Camera camera = makeCamera(description.camera, scene, description.render);
  RenderOptions options;
  options.threads = threads;
  return Renderer(scene, accelerator, camera, description.render).renderImage(options, stats);
}

Image renderMeshes(const SceneDescription& description, std::vector<Mesh> meshes, AccelKind accel,
                   int threads) {
  return renderScene(description, sceneFromMeshes(description, std::move(meshes)), accel, threads);
}

Image renderScene(const SceneDescription& description) {
  return renderScene(description, buildScene(description));
}

void expectEachChangeBelowGoldenFloor(const SceneDescription& description,
                                      std::initializer_list<std::function<void(SceneDescription&)>> changes) {
  const Image unchanged = renderScene(description);
  int index = 0;
  for (const auto& change : changes) {
    SceneDescription changed = description;
    change(changed);
    EXPECT_LT(psnr8(renderScene(changed), unchanged), kRenderGoldenMinPsnrDb) << "change " << index++;
  }
}

}  // namespace lancer::test
