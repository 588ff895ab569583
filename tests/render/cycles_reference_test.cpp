// lancer's path tracer against a committed Blender Cycles render of the same scene: the coarse bracket
// on a floor under a gradient sky and a sun, diffuse materials (tests/data/render/cycles/
// cycles_bracket.toml). The reference, cycles_bracket.exr, is Cycles 3.4 at 16384 samples per pixel,
// made by bench/make_cycles_reference.sh through bench/cycles_scene.py, which maps lancer's units onto
// Cycles' (docs/lighting.md, "Compared with Cycles"). The tolerances are a few times the noise
// measured at these sample counts; a sun off by pi or a missing sky is many times past them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "lancer/image/exr_io.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

constexpr const char* kScene = LANCER_TEST_DATA_DIR "/render/cycles/cycles_bracket.toml";
constexpr const char* kReference = LANCER_TEST_DATA_DIR "/render/cycles/cycles_bracket.exr";
constexpr int kGrid = 4;  // regions per side for the local means

struct Agreement {
  double rmse = 0;          // over every pixel and channel, linear values
  Vec3 meanRatio{0, 0, 0};  // image mean of lancer / Cycles, per channel
  double worstRegion = 0;   // largest |mean lancer / mean Cycles - 1| over the kGrid x kGrid regions
};

Agreement compare(const Image& image, const Image& reference) {
  Agreement agreement;
  double squares = 0;
  Vec3 sum{0, 0, 0}, refSum{0, 0, 0};
  double region[kGrid * kGrid] = {}, refRegion[kGrid * kGrid] = {};
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Vec3 a = image.at(x, y).rgb(), b = reference.at(x, y).rgb(), d = a - b;
      squares += dot(d, d);
      sum += a;
      refSum += b;
      const int cell = y * kGrid / image.height() * kGrid + x * kGrid / image.width();
      region[cell] += a.x + a.y + a.z;
      refRegion[cell] += b.x + b.y + b.z;
    }
  const double pixels = static_cast<double>(image.width()) * image.height();
  agreement.rmse = std::sqrt(squares / (3.0 * pixels));
  agreement.meanRatio = {sum.x / refSum.x, sum.y / refSum.y, sum.z / refSum.z};
  for (int cell = 0; cell < kGrid * kGrid; ++cell)
    agreement.worstRegion = std::max(agreement.worstRegion, std::abs(region[cell] / refRegion[cell] - 1.0));
  std::printf("against Cycles: RMSE %.5f, channel means lancer / Cycles %.4f %.4f %.4f, worst region %.4f\n",
              agreement.rmse, agreement.meanRatio.x, agreement.meanRatio.y, agreement.meanRatio.z,
              agreement.worstRegion);
  return agreement;
}

SceneDescription cyclesScene(int samples) {
  SceneDescription description = loadScene(kScene);
  description.render.samples = samples;
  return description;
}

TEST(CyclesReference, PathTracerAgreesWithCycles) {
  if (!exrSupported()) GTEST_SKIP() << "lancer built without OpenEXR";
  const Image reference = readExr(kReference);
  const Image image = test::renderScene(cyclesScene(256));
  ASSERT_EQ(image.width(), reference.width());
  ASSERT_EQ(image.height(), reference.height());
  const Agreement agreement = compare(image, reference);
  // Measured (lancer 256 samples, Cycles 16384): RMSE 0.0033, channel means equal within 1e-4, the
  // worst of the 16 regions within 0.06%: the limits are 3 to 8 times that, and still far below a 2%
  // error in the sun or the sky.
  EXPECT_LT(agreement.rmse, 0.01);
  EXPECT_NEAR(agreement.meanRatio.x, 1.0, 0.005);
  EXPECT_NEAR(agreement.meanRatio.y, 1.0, 0.005);
  EXPECT_NEAR(agreement.meanRatio.z, 1.0, 0.005);
  EXPECT_LT(agreement.worstRegion, 0.005);
}

// The comparison above is not loose: a sun in the wrong units or a lost sky fails it by far (measured:
// the worst region off by 140% and 55%).
TEST(CyclesReference, WouldCatchASunOffByPiOrAMissingSky) {
  if (!exrSupported()) GTEST_SKIP() << "lancer built without OpenEXR";
  const Image reference = readExr(kReference);
  SceneDescription sunOffByPi = cyclesScene(32);
  sunOffByPi.lights[0].intensity = sunOffByPi.lights[0].intensity * static_cast<float>(std::numbers::pi);
  EXPECT_GT(compare(test::renderScene(sunOffByPi), reference).worstRegion, 0.05);
  SceneDescription noSky = cyclesScene(32);
  noSky.environment.reset();
  EXPECT_GT(compare(test::renderScene(noSky), reference).worstRegion, 0.05);
}

}  // namespace
}  // namespace lancer
