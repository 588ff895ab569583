// A capped cut through a hollow solid shows the hole: gmsh's hollow sphere (tetrahedra between radii
// 1 and 0.5, tests/data/render/hollow_sphere.geo) cut through its centre is capped only across the
// material ring; inside the inner radius the far cavity wall shows, here in its own shadow.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

constexpr int kSize = 48;
constexpr double kViewHeight = 2.5;

// Seen orthographically from +x after removing x > 0; the light, far along (1, 0, 2), lights the cap
// at x = 0 with cos = 1/sqrt(5), and the far cavity wall near the axis lies in the shadow of the
// cavity's upper wall.
SceneDescription cutHollowSphere() {
  SceneDescription d = test::flatLitOnBlue(
      test::orthographicView(kSize, kSize, Vec3d{5, 0, 0}, Vec3d{0, 0, 0}, kViewHeight, Vec3d{0, 0, 1}),
      Vec3d{1000, 0, 2000});
  d.materials = {test::matteMaterial("solid", {0.5f, 0.4f, 0.0f}, {0.6f, 0.5f, 0.0f})};
  d.meshes.resize(1);
  d.clips = {{Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, true}};
  return d;
}

// Pixel column of the point at y (the image's right is +y).
int column(double y) { return static_cast<int>((0.5 + y / kViewHeight) * kSize); }

TEST(ClipCavity, CapCoversTheMaterialRingAndTheCavityShowsItsFarWall) {
  const SceneDescription d = cutHollowSphere();
  const Scene scene =
      test::sceneFromMeshes(d, {readMsh(std::string(LANCER_TEST_DATA_DIR) + "/render/hollow_sphere.msh")});
  const Image image = test::renderScene(d, scene);
  const float capRed = 0.2f * 0.5f + 0.7f * 0.6f / std::sqrt(5.0f);
  const float shadowRed = 0.2f * 0.5f;
  for (const double y : {-0.75, 0.75, 0.6, -0.9}) {  // in the ring 0.5 < r < 1, on the cap
    const Rgba ring = image.at(column(y), kSize / 2);
    EXPECT_NEAR(ring.r, capRed, 1e-3f) << "y = " << y;
    EXPECT_EQ(ring.b, 0.0f) << "y = " << y;
  }
  for (const double y : {0.0, 0.15, -0.2}) {  // in the cavity: its far wall, in shadow, not a cap
    const Rgba hole = image.at(column(y), kSize / 2);
    EXPECT_NEAR(hole.r, shadowRed, 1e-3f) << "y = " << y;
    EXPECT_EQ(hole.b, 0.0f) << "y = " << y;
  }
  // Outside the sphere: the background.
  EXPECT_EQ(image.at(column(1.15), kSize / 2).b, 1.0f);
}

}  // namespace
}  // namespace lancer
