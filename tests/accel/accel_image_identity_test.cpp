// Whole images rendered with the brute-force reference and with the kd-trees are
// identical, pixel for pixel: primary rays, shadow rays to two lights and mirror bounces on a
// gmsh part, so every query the renderer makes goes through the accelerator under test.
#include <gtest/gtest.h>

#include <string>

#include "lancer/mesh/msh_reader.hpp"
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

int differingPixels(const Image& a, const Image& b) {
  int count = 0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      const Rgba p = a.at(x, y), q = b.at(x, y);
      count += !(p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a);
    }
  }
  return count;
}

TEST(AccelImageIdentity, NaiveAndKdTreesRenderTheSameImage) {
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
  for (AccelKind kind : {AccelKind::KdTreeSah, AccelKind::KdTreeMedian}) {
    SCOPED_TRACE(std::string(accelKindName(kind)));
    const Image image = test::renderScene(d, scene, kind, 2);
    ASSERT_EQ(image.width(), reference.width());
    ASSERT_EQ(image.height(), reference.height());
    EXPECT_EQ(differingPixels(image, reference), 0);
  }
}

}  // namespace
}  // namespace lancer
