// The Whitted lighting model on a gmsh sphere against the exact sphere: an orthographic view, one
// light, ambient + diffuse. With Phong shading every pixel inside the silhouette must be within a
// few 1/255 of the closed form; flat shading must be visibly further off (the test can fail).
#include <gtest/gtest.h>

#include <cmath>

#include "lancer/mesh/msh_reader.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

constexpr int kSize = 96;
constexpr double kViewHeight = 2.4;
const Vec3d kLight{3.0, 4.0, 6.0};

SceneDescription sphereScene(ShadingMode shading) {
  SceneDescription d = test::topDownView(kSize, kSize, kViewHeight);
  d.render.shading = shading;
  d.ambient = {0.15f, 0.15f, 0.15f};
  d.lights = {{kLight, {0.9f, 0.8f, 0.7f}, {1, 0, 0}}};
  d.materials = {test::matteMaterial("matte", {0.4f, 0.5f, 0.6f}, {0.7f, 0.6f, 0.5f})};
  d.meshes.resize(1);
  d.meshes[0].smoothAngleDegrees = 80;
  return d;
}

struct SphereErrors {
  double maxInside = 0;  // largest |rendered - exact| over pixels well inside the silhouette, in 1/255
  int pixelsChecked = 0;
};

SphereErrors compareWithExactSphere(ShadingMode shading) {
  const SceneDescription d = sphereScene(shading);
  const Scene scene = test::sceneFromMeshes(d, {readMsh(LANCER_TEST_DATA_DIR "/render/sphere_fine.msh")});
  const Image image = test::renderScene(d, scene);
  const Material& m = d.materials[0];
  SphereErrors errors;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const double wx = ((x + 0.5) / kSize - 0.5) * kViewHeight;
      const double wy = (0.5 - (y + 0.5) / kSize) * kViewHeight;
      const double r2 = wx * wx + wy * wy;
      // The mesh's chords sit inside the exact sphere: leave out the silhouette ring where a pixel
      // may see the background on one and the sphere on the other.
      if (r2 > 0.95 * 0.95) continue;
      const Vec3d point{wx, wy, std::sqrt(1 - r2)};  // also the exact unit normal
      const Vec3d toLight = kLight - point;
      const double cosTheta = std::max(0.0, dot(point, toLight) / length(toLight));
      const Rgba got = image.at(x, y);
      const double expected[3] = {d.ambient.x * m.ka.x + 0.9 * m.kd.x * cosTheta,
                                  d.ambient.y * m.ka.y + 0.8 * m.kd.y * cosTheta,
                                  d.ambient.z * m.ka.z + 0.7 * m.kd.z * cosTheta};
      const double actual[3] = {got.r, got.g, got.b};
      for (int c = 0; c < 3; ++c)
        errors.maxInside = std::max(errors.maxInside, 255 * std::abs(actual[c] - expected[c]));
      ++errors.pixelsChecked;
    }
  }
  return errors;
}

TEST(SphereAnalytic, PhongShadingMatchesTheExactSphereWithinAFew255ths) {
  const SphereErrors phong = compareWithExactSphere(ShadingMode::Phong);
  EXPECT_GT(phong.pixelsChecked, 4000);  // pi 0.95^2 / (2.4/96)^2 = 4536
  EXPECT_LT(phong.maxInside, 3.0) << "largest error, in 1/255";
  RecordProperty("phong_max_error_255", std::to_string(phong.maxInside));
}

TEST(SphereAnalytic, GouraudIsCloseAndFlatShowsItsFacets) {
  const SphereErrors gouraud = compareWithExactSphere(ShadingMode::Gouraud);
  const SphereErrors flat = compareWithExactSphere(ShadingMode::Flat);
  // Gouraud interpolates the exact vertex values linearly: close on a fine mesh.
  EXPECT_LT(gouraud.maxInside, 3.0);
  // Flat uses one normal per facet: off by the facet's angular size, which a viewer sees.
  EXPECT_GT(flat.maxInside, 3.0);
  RecordProperty("gouraud_max_error_255", std::to_string(gouraud.maxInside));
  RecordProperty("flat_max_error_255", std::to_string(flat.maxInside));
}

}  // namespace
}  // namespace lancer
