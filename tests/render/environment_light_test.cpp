// The environment map's importance sampling against quadrature: its pdf integrates to 1 over the
// sphere, sample() returns the pdf that pdf() gives for the same direction, and the estimate
// L cos / pdf of a face's irradiance from a map with a bright sun and a gradient is unbiased.
#include <gtest/gtest.h>

#include <cmath>

#include "lancer/render/environment_light.hpp"
#include "lancer/render/light_sampling.hpp"

namespace lancer {
namespace {

SceneEnvironment sunAndGradientMap() {
  SceneEnvironment environment;
  environment.kind = EnvironmentSettings::Kind::Map;
  environment.up = {0, 0, 1};
  environment.front = {1, 0, 0};
  environment.rotationRadians = 0.4f;
  environment.mapWidth = 32;
  environment.mapHeight = 16;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x) {
      const bool sun = (x == 21 || x == 22) && y == 4;
      const float sky = 0.1f + 0.05f * static_cast<float>(x % 7) + (y < 8 ? 0.3f : 0.0f);
      environment.map.push_back(sun ? Vec3{200, 180, 150} : Vec3{sky, sky * 0.9f, sky * 1.1f});
    }
  return environment;
}

// Integrates f(direction) over the sphere with a fine midpoint rule in (cos theta, phi).
template <typename F>
double overSphere(F f) {
  constexpr int kN = 1024;
  double sum = 0;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < 2 * kN; ++j) {
      const double z = 1 - 2 * (i + 0.5) / kN, phi = 2 * kPi * (j + 0.5) / (2 * kN);
      const double r = std::sqrt(1 - z * z);
      sum += f(Vec3{static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)),
                    static_cast<float>(z)});
    }
  return sum * 4 * kPi / (2.0 * kN * kN);
}

TEST(EnvironmentLight, PdfIntegratesToOne) {
  const EnvironmentLight light(sunAndGradientMap());
  EXPECT_NEAR(overSphere([&](const Vec3& d) { return light.pdf(d); }), 1.0, 0.01);
}

TEST(EnvironmentLight, SampleReturnsThePdfOfItsDirection) {
  const EnvironmentLight light(sunAndGradientMap());
  for (int i = 0; i < 64; ++i) {
    float pdf;
    Vec3 radiance;
    const Vec3 d = light.sample((i % 8 + 0.3f) / 8, (i / 8 + 0.6f) / 8, pdf, radiance);
    EXPECT_NEAR(pdf, light.pdf(d), 1e-3f * pdf);
    EXPECT_EQ(radiance, light.radiance(d));
  }
}

TEST(EnvironmentLight, IrradianceEstimateIsUnbiased) {
  const EnvironmentLight light(sunAndGradientMap());
  for (const Vec3 normal : {Vec3{0, 0, 1}, normalize(Vec3{1, -1, 0.3f}), Vec3{0, 1, 0}}) {
    const double expected =
        overSphere([&](const Vec3& d) { return std::max(0.0f, dot(d, normal)) * light.radiance(d).y; });
    constexpr int kSide = 512;  // a stratified grid of samples
    double sum = 0;
    for (int i = 0; i < kSide; ++i)
      for (int j = 0; j < kSide; ++j) {
        float pdf;
        Vec3 radiance;
        const Vec3 d = light.sample((i + 0.5f) / kSide, (j + 0.5f) / kSide, pdf, radiance);
        if (pdf > 0) sum += std::max(0.0f, dot(d, normal)) * radiance.y / pdf;
      }
    EXPECT_NEAR(sum / (kSide * kSide), expected, 0.01 * expected) << normal.x << "," << normal.y;
  }
}

}  // namespace
}  // namespace lancer
