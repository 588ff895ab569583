// shading = "unlit": the gmsh-made square with the field x + 2 y, tilted in perspective under a
// light with highlights (field_square.toml, the golden's scene), shows at every pixel exactly the
// colour map's colour at that point, in each integrator: no light, no shadow, no fall-off.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "lancer/image/color_map.hpp"
#include "lancer/render/camera.hpp"
#include "lancer/render/sample_sequence.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/files.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

// Largest channel difference, in 8-bit steps, between the picture and magma at (x + 2 y) / 3, over the pixels
// whose sample lands on the square; `seen` counts them.
double worstUnlitError(IntegratorKind integrator, int& seen) {
  SceneDescription description = loadScene(test::dataFile("render/field_square.toml"));
  description.render.srgb = false;  // the map's display values as they are
  description.render.integrator = integrator;
  description.meshes[0].shading = ShadingMode::Unlit;
  // The whole field's range: values clamped at the corners of a face are not linear across it.
  description.meshes[0].colorBy->range = std::pair{0.0, 3.0};
  const Scene scene = buildScene(description);
  const Image image = test::renderScene(description, scene);
  const Camera camera(description.camera, scene.geometry.origin, scene.geometry.bounds, image.width(),
                      image.height());
  double worst = 0;
  seen = 0;
  for (int row = 0; row < image.height(); ++row)
    for (int column = 0; column < image.width(); ++column) {
      // Where the pixel's one sample goes: its centre (Whitted), else the path and AO sampler's point.
      float dx = 0.5f, dy = 0.5f;
      if (integrator != IntegratorKind::Whitted) SampleStream(column, row, 0).next2D(dx, dy);
      const Ray ray = camera.generateRay(static_cast<float>(column) + dx, static_cast<float>(row) + dy);
      const Vec3d origin = scene.geometry.origin + toDouble(ray.origin);
      const Vec3d direction = toDouble(ray.direction);
      const double t = -origin.z / direction.z;  // the square lies in z = 0
      const double x = origin.x + t * direction.x, y = origin.y + t * direction.y;
      constexpr double kInside = 1e-3;
      if (x < kInside || y < kInside || x > 1 - kInside || y > 1 - kInside) continue;
      ++seen;
      const auto value = static_cast<float>((x + 2 * y) / 3);
      const Vec3 expected = colorMapLookup(ColorMapKind::Magma, value);
      const Rgba& pixel = image.at(column, row);
      worst = std::max({worst, std::abs(pixel.r - expected.x) * 255.0, std::abs(pixel.g - expected.y) * 255.0,
                        std::abs(pixel.b - expected.z) * 255.0});
    }
  return worst;
}

TEST(ShadingUnlit, WhittedShowsTheMapColoursUnderALight) {
  int seen = 0;
  EXPECT_LT(worstUnlitError(IntegratorKind::Whitted, seen), 1.0);
  EXPECT_GT(seen, 800);  // of 96 x 72
}

TEST(ShadingUnlit, PathTracerShowsTheMapColours) {
  int seen = 0;
  EXPECT_LT(worstUnlitError(IntegratorKind::Path, seen), 1.0);
  EXPECT_GT(seen, 800);  // of 96 x 72
}

TEST(ShadingUnlit, AmbientOcclusionShowsTheMapColours) {
  int seen = 0;
  EXPECT_LT(worstUnlitError(IntegratorKind::AmbientOcclusion, seen), 1.0);
  EXPECT_GT(seen, 800);  // of 96 x 72
}

TEST(ShadingUnlit, LitShadingDoesNot) {
  // The check above tells: the scene's own Phong shading moves the colours far from the map's.
  SceneDescription description = loadScene(test::dataFile("render/field_square.toml"));
  description.render.srgb = false;
  const Scene scene = buildScene(description);
  const Image image = test::renderScene(description, scene);
  const Rgba& middle = image.at(image.width() / 2, image.height() / 2);
  const Vec3 map = colorMapLookup(ColorMapKind::Magma, static_cast<float>((0.5 + 2 * 0.45 - 0.5) / 2.5));
  EXPECT_GT(std::abs(middle.r - map.x) + std::abs(middle.g - map.y) + std::abs(middle.b - map.z), 0.05f);
}

TEST(ShadingUnlit, IsAShadingNameInTheSceneFile) {
  const SceneDescription description = parseScene(R"(
[render]
shading = "unlit"
[[mesh]]
file = "../fields/node_xy_v41_bin.msh"
shading = "unlit"
)",
                                                  test::dataFile("render/unlit.toml"));
  EXPECT_EQ(description.render.shading, ShadingMode::Unlit);
  EXPECT_EQ(description.meshes.at(0).shading, ShadingMode::Unlit);
}

}  // namespace
}  // namespace lancer
