// The renderer against closed-form answers: the lighting model on a plane, shadows of a square.
#include <gtest/gtest.h>

#include <cmath>

#include "support/test_scenes.hpp"

namespace lancer {
namespace {

Material plainMaterial() {
  Material m;
  m.name = "plain";
  m.ka = {0.3f, 0.2f, 0.1f};
  m.kd = {0.6f, 0.5f, 0.4f};
  m.ks = {0.3f, 0.3f, 0.3f};
  m.shininess = 12;
  return m;
}

// An orthographic camera at height 5 looking down -z at a window `viewHeight` tall.
SceneDescription topDownScene(int width, int height, double viewHeight) {
  SceneDescription d = test::topDownView(width, height, viewHeight);
  d.render.background = {0, 0, 0};
  d.ambient = {0.2f, 0.2f, 0.2f};
  d.materials = {plainMaterial()};
  return d;
}

// Centre of pixel (x, y) in world coordinates for topDownScene (scene origin at 0).
void pixelCentre(const SceneDescription& d, int x, int y, double& wx, double& wy) {
  const double h = *d.camera.viewHeight, w = h * d.render.width / d.render.height;
  wx = ((x + 0.5) / d.render.width - 0.5) * w;
  wy = (0.5 - (y + 0.5) / d.render.height) * h;
}

TEST(RenderAnalytic, PlaneMatchesLightingModelEveryPixel) {
  for (ShadingMode shading : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
    SceneDescription d = topDownScene(40, 30, 3.0);
    d.render.shading = shading;
    d.lights = {{{1.0, 2.0, 3.0}, {0.9f, 0.8f, 0.7f}, {1, 0, 0}}};
    d.meshes.resize(1);
    const Scene scene = test::sceneFromMeshes(d, {test::squareMesh(-4, -4, 4, 4, 0)});
    ASSERT_EQ(scene.geometry.origin.x, 0.0);
    const Image image = test::renderScene(d, scene);
    const Material m = plainMaterial();
    for (int y = 0; y < d.render.height; ++y) {
      for (int x = 0; x < d.render.width; ++x) {
        double wx = 0, wy = 0;
        pixelCentre(d, x, y, wx, wy);
        const Vec3 p{float(wx), float(wy), 0};
        const Vec3 toLight = Vec3{1, 2, 3} - p;
        const float distance = length(toLight);
        const Vec3 l = toLight * (1 / distance);
        const Vec3 n{0, 0, 1}, v{0, 0, 1};
        const float cosTheta = dot(n, l);
        Vec3 expected = d.ambient * m.ka;
        if (shading == ShadingMode::Gouraud) {
          // Gouraud interpolates the corner values bilinearly: evaluate the model at the 4 corners.
          const float u = float((wx + 4) / 8), w = float((wy + 4) / 8);
          const Vec3 corners[4] = {{-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}};
          const float weights[4] = {(1 - u) * (1 - w), u * (1 - w), u * w, (1 - u) * w};
          for (int c = 0; c < 4; ++c) {
            const Vec3 lc = normalize(Vec3{1, 2, 3} - corners[c]);
            const Vec3 r = n * (2 * dot(n, lc)) - lc;
            expected += Vec3{0.9f, 0.8f, 0.7f} *
                        (m.kd * dot(n, lc) + m.ks * std::pow(std::max(0.f, dot(r, v)), 12.f)) * weights[c];
          }
        } else {
          const Vec3 r = n * (2 * cosTheta) - l;
          expected +=
              Vec3{0.9f, 0.8f, 0.7f} * (m.kd * cosTheta + m.ks * std::pow(std::max(0.f, dot(r, v)), 12.f));
        }
        const Rgba got = image.at(x, y);
        ASSERT_NEAR(got.r, expected.x, 2e-4) << "pixel " << x << "," << y << " shading " << int(shading);
        ASSERT_NEAR(got.g, expected.y, 2e-4) << "pixel " << x << "," << y;
        ASSERT_NEAR(got.b, expected.z, 2e-4) << "pixel " << x << "," << y;
      }
    }
  }
}

TEST(RenderAnalytic, SquareOccluderShadowsExactlyItsProjection) {
  // Floor at z = 0, a 1x1 occluder at z = 1, a light at (0, 0, 10): the shadow is the occluder
  // scaled by 10/9 about the axis, i.e. |x|, |y| < 0.5556. The camera sees the occluder itself
  // where |x|, |y| < 0.5.
  SceneDescription d = topDownScene(64, 64, 2.0);
  d.lights = {{{0, 0, 10}, {1, 1, 1}, {1, 0, 0}}};
  d.render.shading = ShadingMode::Flat;
  Material floor = plainMaterial();
  floor.ks = {0, 0, 0};
  d.materials = {floor};
  d.meshes.resize(2);
  const Scene scene = test::sceneFromMeshes(
      d, {test::squareMesh(-2, -2, 2, 2, 0), test::squareMesh(-0.5f, -0.5f, 0.5f, 0.5f, 1)});
  const Image image = test::renderScene(d, scene);
  const float ambientOnly = d.ambient.x * floor.ka.x;
  int shadowed = 0;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      double wx = 0, wy = 0;
      pixelCentre(d, x, y, wx, wy);
      const bool seesOccluder = std::abs(wx) < 0.5 && std::abs(wy) < 0.5;
      const bool inShadow = std::abs(wx) < 0.5 * 10 / 9 && std::abs(wy) < 0.5 * 10 / 9;
      const float value = image.at(x, y).r;
      if (seesOccluder) {
        EXPECT_GT(value, ambientOnly + 0.1f) << x << "," << y;
      } else if (inShadow) {
        EXPECT_FLOAT_EQ(value, ambientOnly) << "expected shadow at " << x << "," << y;
        ++shadowed;
      } else {
        EXPECT_GT(value, ambientOnly + 0.1f) << "expected light at " << x << "," << y;
      }
    }
  }
  EXPECT_GT(shadowed, 0);
}

TEST(RenderAnalytic, BitIdenticalForAnyThreadCount) {
  SceneDescription d = topDownScene(70, 50, 2.5);  // tiles that do not divide the image
  d.render.samples = 4;
  d.render.sampler = SamplerKind::Stratified;
  d.lights = {{{0.3, -0.2, 4}, {1, 1, 1}, {1, 0, 0}}};
  d.meshes.resize(2);
  const Scene scene = test::sceneFromMeshes(
      d, {test::squareMesh(-2, -2, 2, 2, 0), test::squareMesh(-0.4f, -0.7f, 0.6f, 0.2f, 1)});
  const Image one = test::renderScene(d, scene, AccelKind::KdTreeSah, 1);
  EXPECT_TRUE(one == test::renderScene(d, scene, AccelKind::KdTreeSah, 2));
  EXPECT_TRUE(one == test::renderScene(d, scene, AccelKind::KdTreeSah, 3));
  EXPECT_TRUE(one == test::renderScene(d, scene, AccelKind::Naive, 2));
}

TEST(RenderAnalytic, FarFromOriginRendersLikeAtOrigin) {
  // The same scene translated to x = 1e6 (survey coordinates) gives the same picture.
  SceneDescription d = topDownScene(48, 48, 2.0);
  d.lights = {{{0.5, 0.5, 3}, {1, 1, 1}, {1, 0, 0}}};
  d.meshes.resize(2);
  const Image atOrigin = test::renderMeshes(
      d, {test::squareMesh(-2, -2, 2, 2, 0), test::squareMesh(-0.5f, -0.5f, 0.5f, 0.5f, 1)});
  SceneDescription far = d;
  const double offset = 1e6;
  far.camera.position->x += offset;
  far.camera.lookAt->x += offset;
  far.lights[0].position.x += offset;
  for (MeshInstance& instance : far.meshes) instance.translate = {offset, 0, 0};
  const Image translated = test::renderMeshes(
      far, {test::squareMesh(-2, -2, 2, 2, 0), test::squareMesh(-0.5f, -0.5f, 0.5f, 0.5f, 1)});
  double maxDifference = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x)
      maxDifference = std::max(maxDifference, double(std::abs(atOrigin.at(x, y).r - translated.at(x, y).r)));
  EXPECT_LT(maxDifference, 1.0 / 255);
}

}  // namespace
}  // namespace lancer
