// The path tracer's adaptive rounds (`adaptive_noise`): the noisy pixels of a picture get more samples
// than the flat ones, each pixel's value is a plain render's at its own count, the picture (with the
// denoiser's variances) has the same bytes for any thread count and band split, and the displayed
// error follows the tone curve and encoding.
#include <gtest/gtest.h>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/render/pixel_loop.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

// A diffuse sphere under a sun in a sky, seen from above against a black background: the sphere's rim
// is noisy (some samples of a pixel see the lit sphere, some the black), the background is the same
// for every sample.
SceneDescription sphereUnderSun(int samples, float adaptiveNoise) {
  SceneDescription d = test::topDownView(40, 40, 2.4);
  d.render.integrator = IntegratorKind::Path;
  d.render.samples = samples;
  d.render.adaptiveNoise = adaptiveNoise;
  d.render.maxBounces = 4;
  d.ambient = {0, 0, 0};
  d.materials = {test::matteMaterial("matte", {0, 0, 0}, {0.6f, 0.6f, 0.6f})};
  d.materials[0].ks = {0, 0, 0};
  EnvironmentSettings environment;
  environment.color = {0.3f, 0.35f, 0.4f};
  d.environment = environment;
  PointLight sun;
  sun.type = LightType::Sun;
  sun.direction = normalize(Vec3d{1, 0.5, 1});
  sun.angleDegrees = 10;
  d.lights = {sun};
  d.meshes.resize(1);
  d.meshes[0].smoothAngleDegrees = 80;
  return d;
}

struct Rendered {
  Scene scene;
  Accelerator accelerator;
  Camera camera;
  Rendered(const SceneDescription& d)
      : scene(test::sceneFromMeshes(d, {readMsh(LANCER_TEST_DATA_DIR "/render/sphere_fine.msh")})),
        accelerator(Accelerator::build(scene.geometry.positions, scene.geometry.faces, AccelKind::KdTreeSah)),
        camera(makeCamera(d.camera, scene, d.render)) {}
};

int samplesOf(const Renderer& renderer, int x, int y, Rgba* value = nullptr) {
  TraceCounters counters;
  std::uint64_t samples = 0;
  const Rgba pixel = renderer.renderPixel(x, y, counters, samples);
  if (value != nullptr) *value = pixel;
  return static_cast<int>(samples);
}

TEST(AdaptiveRounds, NoisyPixelsGetMoreSamplesThanFlatOnes) {
  const SceneDescription d = sphereUnderSun(64, 0.01f);
  const Rendered r(d);
  const Renderer renderer(r.scene, r.accelerator, r.camera, d.render);
  // A corner of the background and its whole neighbourhood see the same black: the first pass only.
  EXPECT_EQ(samplesOf(renderer, 1, 1), adaptiveFirstPass(64));
  // The sphere's rim, where a pixel's samples see the lit sphere or the black: all the samples.
  EXPECT_EQ(samplesOf(renderer, 20, 2), 64);
  RenderStats stats;
  renderer.renderImage(RenderOptions{}, &stats);
  EXPECT_GT(stats.samplesPerPixel, adaptiveFirstPass(64));
  EXPECT_LT(stats.samplesPerPixel, 64);
}

TEST(AdaptiveRounds, APixelIsThePlainRenderAtItsOwnCount) {
  const SceneDescription d = sphereUnderSun(64, 0.01f);
  const Rendered r(d);
  const Renderer renderer(r.scene, r.accelerator, r.camera, d.render);
  const Image image = renderer.renderImage(RenderOptions{});
  for (const auto& [x, y] : {std::pair{20, 20}, std::pair{13, 26}, std::pair{1, 1}, std::pair{39, 39}}) {
    Rgba value;
    const int count = samplesOf(renderer, x, y, &value);
    EXPECT_EQ(value, image.at(x, y)) << x << "," << y;  // renderPixel renders the pixel's tile
    SceneDescription plain = d;
    plain.render.adaptiveNoise = 0;
    plain.render.samples = count;
    const Renderer fixed(r.scene, r.accelerator, r.camera, plain.render);
    Rgba fixedValue;
    EXPECT_EQ(samplesOf(fixed, x, y, &fixedValue), count);
    EXPECT_EQ(fixedValue, value) << x << "," << y;
  }
}

TEST(AdaptiveRounds, SameBytesForAnyThreadCountAndBandSplitWithTheDenoiser) {
  SceneDescription d = sphereUnderSun(32, 0.02f);
  d.render.width = 40;
  d.render.height = 70;
  d.render.denoise = true;
  const Rendered r(d);
  const Renderer renderer(r.scene, r.accelerator, r.camera, d.render);
  RenderOptions one, three;
  one.threads = 1;
  three.threads = 3;
  FeatureBuffers featuresOne, featuresThree;
  const Image a = renderer.renderFinal(one, nullptr, &featuresOne);
  const Image b = renderer.renderFinal(three, nullptr, &featuresThree);
  const Image rows = renderer.renderRows(BandRange{1, 1}, RenderOptions{});
  const Image undenoised = renderer.renderImage(one);
  for (int y = 0; y < d.render.height; ++y)
    for (int x = 0; x < d.render.width; ++x) {
      ASSERT_EQ(a.at(x, y), b.at(x, y)) << x << "," << y;
      const std::size_t k = featuresOne.index(x, y);
      ASSERT_EQ(featuresOne.variance[k], featuresThree.variance[k]) << x << "," << y;
      if (y >= 32 && y < 64) {
        ASSERT_EQ(undenoised.at(x, y), rows.at(x, y - 32)) << x << "," << y;
      }
    }
  // Each pixel's variance is its own mean's: none where the samples agree, some on the sphere.
  EXPECT_EQ(featuresOne.variance[featuresOne.index(1, 1)], 0.0f);
  EXPECT_GT(featuresOne.variance[featuresOne.index(20, 35)], 0.0f);
}

TEST(AdaptiveRounds, DisplayedErrorFollowsTheToneCurveAndEncoding) {
  RenderSettings linear;
  linear.srgb = false;
  EXPECT_NEAR(displayedError(0.5, 0.1, linear), 0.1f, 1e-6f);
  EXPECT_EQ(displayedError(2.0, 0.1, linear), 0.0f);              // white either way
  EXPECT_NEAR(displayedError(0.95, 0.1, linear), 0.075f, 1e-6f);  // clipped above white
  linear.exposure = 1;  // twice as bright on screen, twice the error
  EXPECT_NEAR(displayedError(0.2, 0.05, linear), 0.1f, 1e-6f);
  RenderSettings srgb;  // the encoding's slope: steep in the darks, flat in the lights
  EXPECT_GT(displayedError(0.02, 0.005, srgb), 2 * 0.005f);
  EXPECT_LT(displayedError(0.6, 0.05, srgb), 0.05f);
  EXPECT_EQ(adaptiveFirstPass(1), 1);
  EXPECT_EQ(adaptiveFirstPass(8), 2);
  EXPECT_EQ(adaptiveFirstPass(32), 4);
  EXPECT_EQ(adaptiveFirstPass(1024), 8);
}

}  // namespace
}  // namespace lancer
