#include "support/test_scenes.hpp"

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

Material ambientOnlyMaterial(const char* name, Vec3 ka) {
  Material m;
  m.name = name;
  m.ka = ka;
  m.kd = {0, 0, 0};
  m.ks = {0, 0, 0};
  return m;
}

Scene sceneFromMeshes(const SceneDescription& description, std::vector<Mesh> meshes) {
  return buildScene(description, std::move(meshes));
}

Image renderScene(const SceneDescription& description, const Scene& scene, AccelKind accel, int threads) {
  const Accelerator accelerator = Accelerator::build(scene.positions, scene.faces, accel);
  const Camera camera = makeCamera(description.camera, scene, description.render);
  RenderOptions options;
  options.threads = threads;
  return Renderer(scene, accelerator, camera, description.render).renderImage(options);
}

Image renderScene(const SceneDescription& description) { return renderScene(description, buildScene(description)); }

}  // namespace lancer::test
