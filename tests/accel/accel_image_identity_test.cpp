// Whole images rendered with the brute-force reference, the BVH and the kd-trees are
// identical, pixel for pixel: primary rays, shadow rays to two lights and mirror bounces on a
// gmsh part, so every query the renderer makes goes through the accelerator under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/render/renderer.hpp"
#include "support/test_images.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

SceneDescription blockScene() {
  SceneDescription d;
  d.render.width = 96;
  d.render.height = 72;
  d.render.maxDepth = 2;  // reflections: secondary rays start on the surface, in any direction
  d.render.shading = ShadingMode::Phong;
  d.camera.position = Vec3d{7.5, -5.0, 6.0};
  d.camera.up = Vec3d{0, 0, 1};
  d.ambient = {0.1f, 0.1f, 0.1f};
  d.lights = {{{6.0, -3.0, 8.0}, {0.8f, 0.8f, 0.8f}, {1, 0, 0}},
              {{-2.0, 5.0, 3.0}, {0.4f, 0.3f, 0.3f}, {1, 0, 0}}};
  Material m;
  m.name = "shiny";
  m.reflectivity = {0.3f, 0.3f, 0.3f};
  d.materials = {m};
  d.meshes.resize(1);
  return d;
}

TEST(AccelImageIdentity, NaiveBvhAndKdTreesRenderTheSameImage) {
  const SceneDescription d = blockScene();
  const Scene scene =
      test::sceneFromMeshes(d, {readMsh(std::string(LANCER_TEST_DATA_DIR) + "/accel/holed_block.msh")});
  const Image reference = test::renderScene(d, scene, AccelKind::Naive, 2);
  // The part fills a good share of the frame, so the comparison is not one of empty backgrounds.
  int lit = 0;
  for (int y = 0; y < reference.height(); ++y) {
    for (int x = 0; x < reference.width(); ++x) lit += reference.at(x, y).r != reference.at(0, 0).r;
  }
  ASSERT_GT(lit, reference.width() * reference.height() / 5);
  for (AccelKind kind :
       {AccelKind::Bvh, AccelKind::KdTreeSah, AccelKind::KdTreeSahExact, AccelKind::KdTreeMedian}) {
    SCOPED_TRACE(std::string(accelKindName(kind)));
    const Image image = test::renderScene(d, scene, kind, 2);
    ASSERT_EQ(image.width(), reference.width());
    ASSERT_EQ(image.height(), reference.height());
    EXPECT_EQ(test::differingPixels(image, reference), 0);
  }
}

// --threads bounds the build: the default tree built on 1, 2 and 3 threads (its parallel top
// reaching the fixture's cells) is the same tree, word for word, and renders the same image.
TEST(AccelImageIdentity, TreeAndImageIdenticalForAnyBuildThreadCount) {
  const SceneDescription d = blockScene();
  const Scene scene =
      test::sceneFromMeshes(d, {readMsh(std::string(LANCER_TEST_DATA_DIR) + "/accel/holed_block.msh")});
  const Camera camera = makeCamera(d.camera, scene, d.render);
  RenderOptions render;
  render.threads = 2;
  auto buildWith = [&](int threads) {
    KdBuildOptions options;
    options.threads = threads;
    options.parallelSplitAbove = 64;
    return Accelerator::build(scene.geometry.positions, scene.geometry.faces, AccelKind::KdTreeSah, options);
  };
  const Accelerator one = buildWith(1);
  const Image reference = Renderer(scene, one, camera, d.render).renderImage(render);
  const KdTree oneTree = KdTree::buildSah(scene.geometry.positions, scene.geometry.faces, [] {
    KdBuildOptions o;
    o.threads = 1;
    return o;
  }());
  for (int threads : {2, 3}) {
    SCOPED_TRACE(threads);
    const Accelerator many = buildWith(threads);
    EXPECT_EQ(many.stats().nodes, one.stats().nodes);
    EXPECT_EQ(many.stats().triangleReferences, one.stats().triangleReferences);
    EXPECT_EQ(test::differingPixels(Renderer(scene, many, camera, d.render).renderImage(render), reference),
              0);
    KdBuildOptions o;
    o.threads = threads;
    o.parallelSplitAbove = 64;
    const KdTree tree = KdTree::buildSah(scene.geometry.positions, scene.geometry.faces, o);
    ASSERT_EQ(tree.layout().size(), oneTree.layout().size());
    EXPECT_TRUE(std::equal(
        tree.layout().begin(), tree.layout().end(), oneTree.layout().begin(),
        [](const KdNode& a, const KdNode& b) { return a.payload == b.payload && a.bits == b.bits; }));
  }
}

// The default BVH built on 1 to 4 threads: the same tree (bvh_test.cpp compares it byte for byte with
// its parallel top reaching small ranges) and the same image.
TEST(AccelImageIdentity, BvhImageIdenticalForAnyBuildThreadCount) {
  const SceneDescription d = blockScene();
  const Scene scene =
      test::sceneFromMeshes(d, {readMsh(std::string(LANCER_TEST_DATA_DIR) + "/accel/holed_block.msh")});
  const Camera camera = makeCamera(d.camera, scene, d.render);
  RenderOptions render;
  render.threads = 2;
  auto buildWith = [&](int threads) {
    KdBuildOptions options;
    options.threads = threads;
    return Accelerator::build(scene.geometry.positions, scene.geometry.faces, AccelKind::Bvh, options);
  };
  const Accelerator one = buildWith(1);
  const Image reference = Renderer(scene, one, camera, d.render).renderImage(render);
  for (int threads : {2, 3, 4}) {
    SCOPED_TRACE(threads);
    const Accelerator many = buildWith(threads);
    EXPECT_EQ(many.stats().nodes, one.stats().nodes);
    EXPECT_EQ(many.stats().sahCost, one.stats().sahCost);
    EXPECT_EQ(test::differingPixels(Renderer(scene, many, camera, d.render).renderImage(render), reference),
              0);
  }
}

}  // namespace
}  // namespace lancer
