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

// The holed block's scene, camera and render options, rendered with any accelerator.
struct BlockRender {
  SceneDescription d = blockScene();
  Scene scene =
      test::sceneFromMeshes(d, {readMsh(std::string(LANCER_TEST_DATA_DIR) + "/accel/holed_block.msh")});
  Camera camera = makeCamera(d.camera, scene, d.render);
  RenderOptions render = [] {
    RenderOptions options;
    options.threads = 2;
    return options;
  }();
  // The accelerator of `kind` built on `threads` threads, forking subtrees above `parallelSplitAbove`
  // triangles when given (the fixture is small: the default forks none).
  Accelerator build(AccelKind kind, int threads, int parallelSplitAbove = 0) const {
    KdBuildOptions options;
    options.threads = threads;
    if (parallelSplitAbove > 0) options.parallelSplitAbove = static_cast<std::uint32_t>(parallelSplitAbove);
    return Accelerator::build(scene.geometry.positions, scene.geometry.faces, kind, options);
  }
  Image with(const Accelerator& accelerator) const {
    return Renderer(scene, accelerator, camera, d.render).renderImage(render);
  }
};

// --threads bounds the build: the default tree built on 1, 2 and 3 threads (its parallel top
// reaching the fixture's cells) is the same tree, word for word, and renders the same image.
TEST(AccelImageIdentity, TreeAndImageIdenticalForAnyBuildThreadCount) {
  const BlockRender block;
  const Scene& scene = block.scene;
  auto buildWith = [&](int threads) { return block.build(AccelKind::KdTreeSah, threads, 64); };
  const Accelerator one = buildWith(1);
  const Image reference = block.with(one);
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
    EXPECT_EQ(test::differingPixels(block.with(many), reference), 0);
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
  const BlockRender block;
  auto buildWith = [&](int threads) { return block.build(AccelKind::Bvh, threads); };
  const Accelerator one = buildWith(1);
  const Image reference = block.with(one);
  for (int threads : {2, 3, 4}) {
    SCOPED_TRACE(threads);
    const Accelerator many = buildWith(threads);
    EXPECT_EQ(many.stats().nodes, one.stats().nodes);
    EXPECT_EQ(many.stats().sahCost, one.stats().sahCost);
    EXPECT_EQ(test::differingPixels(block.with(many), reference), 0);
  }
}

}  // namespace
}  // namespace lancer
