#include "lancer/render/lighting.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lancer {
namespace {

Material testMaterial() {
  Material m;
  m.kd = {0.5f, 0.25f, 1.0f};
  m.ks = {0.4f, 0.4f, 0.4f};
  m.shininess = 10;
  return m;
}

TEST(Lighting, DiffuseFollowsCosineLaw) {
  Material m = testMaterial();
  m.ks = {0, 0, 0};
  const SceneLight light{{0, 0, 0}, {1, 1, 1}, {1, 0, 0}};
  const Vec3 n{0, 0, 1};
  const float angle = 0.7f;
  const Vec3 l{std::sin(angle), 0, std::cos(angle)};
  const Vec3 c = directLighting(m, light, n, n, l, 3.0f);
  EXPECT_FLOAT_EQ(c.x, 0.5f * std::cos(angle));
  EXPECT_FLOAT_EQ(c.y, 0.25f * std::cos(angle));
  EXPECT_FLOAT_EQ(c.z, 1.0f * std::cos(angle));
}

TEST(Lighting, SpecularPeaksOnMirrorDirection) {
  const Material m = testMaterial();
  const SceneLight light{{0, 0, 0}, {1, 1, 1}, {1, 0, 0}};
  const Vec3 n{0, 0, 1};
  const Vec3 l = normalize(Vec3{1, 0, 1});
  const Vec3 mirror = normalize(Vec3{-1, 0, 1});
  const Vec3 c = directLighting(m, light, n, mirror, l, 1.0f);
  EXPECT_NEAR(c.x, 0.5f * std::sqrt(0.5f) + 0.4f, 1e-5);
  // Off the mirror direction by alpha: ks * cos(alpha)^n.
  const float alpha = 0.3f;
  const Vec3 view{-std::sin(0.785398f + alpha), 0, std::cos(0.785398f + alpha)};
  const Vec3 c2 = directLighting(m, light, n, view, l, 1.0f);
  EXPECT_NEAR(c2.x, 0.5f * std::sqrt(0.5f) + 0.4f * std::pow(std::cos(alpha), 10.0f), 1e-5);
}

TEST(Lighting, NoLightFromBehindNoSpecularEither) {
  const Material m = testMaterial();
  const SceneLight light{{0, 0, 0}, {1, 1, 1}, {1, 0, 0}};
  const Vec3 n{0, 0, 1};
  const Vec3 c = directLighting(m, light, n, n, Vec3{0, 0.2f, -1}, 1.0f);
  EXPECT_EQ(c, (Vec3{0, 0, 0}));
}

TEST(Lighting, AttenuationWithDistance) {
  Material m = testMaterial();
  m.ks = {0, 0, 0};
  const SceneLight light{{0, 0, 0}, {2, 2, 2}, {1, 0.5f, 0.25f}};
  const Vec3 n{0, 0, 1};
  const Vec3 c = directLighting(m, light, n, n, n, 2.0f);
  EXPECT_FLOAT_EQ(c.x, 2 * 0.5f / (1 + 0.5f * 2 + 0.25f * 4));
}

}  // namespace
}  // namespace lancer
