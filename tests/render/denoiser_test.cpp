// The denoiser against analytic oracles: synthetic images of known edges with seeded noise, where the
// truth is the image before the noise. It must lower the error, and never carry light across a
// shadow edge, an element edge (albedo), a silhouette (depth) or a crease (normal).
#include "lancer/render/denoiser.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

#include "lancer/image/image_difference.hpp"
#include "support/seeded_noise.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

constexpr int kSize = 64;
constexpr int kEdge = 32;  // columns x < kEdge are the left side

// The mean red value of column x.
double columnMean(const Image& image, int x) {
  double sum = 0;
  for (int y = 0; y < image.height(); ++y) sum += image.at(x, y).r;
  return sum / image.height();
}

// A plane facing the viewer 10 units away, albedo 0.7 everywhere; `left` and `right` pick each
// side's features.
struct Side {
  float radiance = 0.5f;
  float albedo = 0.7f;
  float depth = 10;
  Vec3 normal{0, 0, 1};
};

void makeScene(const Side& left, const Side& right, Image& clean, FeatureBuffers& features) {
  clean = Image(kSize, kSize);
  features = FeatureBuffers(kSize, kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const Side& s = x < kEdge ? left : right;
      clean.setRgb(x, y, Vec3{1, 1, 1} * s.radiance);
      const std::size_t k = features.index(x, y);
      features.albedo[k] = Vec3{1, 1, 1} * s.albedo;
      features.depth[k] = s.depth;
      features.normal[k] = s.normal;
    }
}

// Denoises the noisy image and checks that the two columns beside the edge keep their side's value
// (the mean over 64 rows: smearing shifts it, noise alone leaves it within a few thousandths).
void expectEdgeKept(const Side& left, const Side& right, float sigma) {
  Image clean;
  FeatureBuffers features;
  makeScene(left, right, clean, features);
  const Image noisy = test::withSeededNoise(clean, sigma);
  const Image denoised = denoise(noisy, features);
  EXPECT_NEAR(columnMean(denoised, kEdge - 1), left.radiance, 0.012);
  EXPECT_NEAR(columnMean(denoised, kEdge), right.radiance, 0.012);
  EXPECT_LT(rootMeanSquareDifference(denoised, clean), 0.6 * rootMeanSquareDifference(noisy, clean));
}

TEST(Denoiser, KeepsAShadowEdgeSharp) {
  // The same plane, albedo, normal and depth on both sides: only the light changes.
  expectEdgeKept(Side{.radiance = 0.7f}, Side{.radiance = 0.175f}, 0.04f);
}

TEST(Denoiser, KeepsAnElementEdgeOfAnotherColour) {
  // Two elements of albedo 0.5 and 0.45 under the same light: a step no bigger than the noise,
  // kept by the albedo buffer alone.
  expectEdgeKept(Side{.radiance = 0.5f, .albedo = 0.5f}, Side{.radiance = 0.45f, .albedo = 0.45f}, 0.04f);
}

TEST(Denoiser, KeepsASilhouetteAgainstAFarSurface) {
  // The same albedo and normal, 10 and 50 units away: the depth buffer keeps them apart.
  expectEdgeKept(Side{.radiance = 0.5f}, Side{.radiance = 0.46f, .depth = 50}, 0.04f);
}

TEST(Denoiser, KeepsACreaseBetweenTwoFaces) {
  // A fold: the depth is continuous, the normal turns by 90 degrees.
  expectEdgeKept(Side{.radiance = 0.5f}, Side{.radiance = 0.46f, .normal = {1, 0, 0}}, 0.04f);
}

TEST(Denoiser, KeepsASilhouetteAgainstTheBackground) {
  Side background{.radiance = 0.46f,
                  .albedo = 0.7f,
                  .depth = std::numeric_limits<float>::infinity(),
                  .normal = {0, 0, 0}};
  expectEdgeKept(Side{.radiance = 0.5f}, background, 0.04f);
}

TEST(Denoiser, NoiseEstimateMatchesTheNoiseAdded) {
  Image clean;
  FeatureBuffers features;
  makeScene(Side{}, Side{.radiance = 0.2f, .depth = 30}, clean, features);
  // The deviation found is the one added, whatever the albedo.
  Image demodulated = test::withSeededNoise(clean, 0.05f);
  EXPECT_NEAR(estimateNoise(demodulated, features), 0.05, 0.006);
}

TEST(Denoiser, LeavesACleanImageAlmostAsItIs) {
  Image clean;
  FeatureBuffers features;
  makeScene(Side{.radiance = 0.7f}, Side{.radiance = 0.2f, .depth = 30}, clean, features);
  // A smooth ramp of light on top: no noise to find, so nothing to smooth.
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) clean.at(x, y).g += 0.004f * static_cast<float>(x + y);
  EXPECT_LT(rootMeanSquareDifference(denoise(clean, features), clean), 1e-3);
}

// A plane with noise of deviation 0.04 and, every 8 pixels, a firefly: one sample of 40 among 8,
// a pixel at 5 whose samples spread as much (the variance the path tracer reports), the others'
// variance that of their noise. Returns the largest error at a firefly after denoising.
float worstFireflyError(bool varianceKnown) {
  Image clean;
  FeatureBuffers features;
  makeScene(Side{}, Side{}, clean, features);
  Image noisy = test::withSeededNoise(clean, 0.04f);
  constexpr float kFirefly = 5.0f;
  for (int y = 4; y < kSize; y += 8)
    for (int x = 4; x < kSize; x += 8) noisy.setRgb(x, y, Vec3{1, 1, 1} * kFirefly);
  if (varianceKnown)
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        features.variance[features.index(x, y)] =
            noisy.at(x, y).r == kFirefly ? kFirefly * kFirefly * 7 / 8 : 0.04f * 0.04f;
  const Image denoised = denoise(noisy, features);
  float worst = 0;
  for (int y = 4; y < kSize; y += 8)
    for (int x = 4; x < kSize; x += 8) worst = std::max(worst, std::abs(denoised.at(x, y).r - 0.5f));
  return worst;
}

TEST(Denoiser, TakesInAFireflyWhoseSamplesSpreadWide) {
  // Its own variance lets the pixel take its neighbours in; without it (no variance from the
  // samples), a firefly is a colour edge far above the noise and stays.
  EXPECT_LT(worstFireflyError(true), 0.1f);
  EXPECT_GT(worstFireflyError(false), 1.0f);
}

// A render of two squares, the upper one shadowing the lower, in two colours: the clean render's
// own feature buffers guide the denoiser of its noisy copy.
struct RenderedScene {
  Image clean;
  FeatureBuffers features;
};

RenderedScene renderTwoSquares(int threads) {
  SceneDescription description = test::flatLitOnBlue(test::topDownView(96, 96, 4.0), {1.5, 1.0, 6.0});
  description.render.samples = 4;
  description.materials = {test::matteMaterial("grey", {0.2f, 0.2f, 0.2f}, {0.7f, 0.7f, 0.7f}),
                           test::matteMaterial("warm", {0.2f, 0.15f, 0.1f}, {0.8f, 0.5f, 0.3f})};
  description.meshes.resize(2);
  description.meshes[1].material = 1;
  std::vector<Mesh> meshes;
  meshes.push_back(test::squareMesh(-1.8f, -1.8f, 1.8f, 1.8f, 0.0f));
  meshes.push_back(test::squareMesh(-0.6f, -0.6f, 0.6f, 0.6f, 1.0f));
  const Scene scene = test::sceneFromMeshes(description, std::move(meshes));
  const Accelerator accelerator =
      Accelerator::build(scene.geometry.positions, scene.geometry.faces, AccelKind::KdTreeSah);
  const Camera camera = makeCamera(description.camera, scene, description.render);
  const Renderer renderer(scene, accelerator, camera, description.render);
  RenderOptions options;
  options.threads = threads;
  return {renderer.renderImage(options), renderer.renderFeatures(threads)};
}

TEST(Denoiser, LowersTheErrorOfANoisyRender) {
  const RenderedScene scene = renderTwoSquares(0);
  for (const float sigma : {0.02f, 0.05f, 0.1f}) {
    const Image noisy = test::withSeededNoise(scene.clean, sigma);
    const double before = rootMeanSquareDifference(noisy, scene.clean),
                 after = rootMeanSquareDifference(denoise(noisy, scene.features), scene.clean);
    EXPECT_LT(after, 0.35 * before) << "noise " << sigma << ": RMSE " << before << " -> " << after;
  }
}

TEST(Denoiser, FeatureBuffersSeeTheSurfaces) {
  const RenderedScene scene = renderTwoSquares(0);
  const FeatureBuffers& f = scene.features;
  const std::size_t upper = f.index(48, 48), lower = f.index(10, 80), outside = f.index(1, 1);
  EXPECT_NEAR(f.depth[upper], 4.0f, 1e-4f);  // the camera is at z = 5
  EXPECT_NEAR(f.depth[lower], 5.0f, 1e-4f);
  EXPECT_TRUE(std::isinf(f.depth[outside]));
  EXPECT_NEAR(f.albedo[upper].y, 0.5f, 1e-6f);
  EXPECT_NEAR(f.albedo[lower].y, 0.7f, 1e-6f);
  EXPECT_NEAR(f.normal[upper].z, 1.0f, 1e-6f);
  EXPECT_EQ(f.normal[outside].z, 0.0f);
}

TEST(Denoiser, SameResultForAnyThreadCount) {
  const RenderedScene one = renderTwoSquares(1), four = renderTwoSquares(4);
  EXPECT_EQ(one.features.albedo, four.features.albedo);
  EXPECT_EQ(one.features.depth, four.features.depth);
  const Image noisy = test::withSeededNoise(one.clean, 0.05f);
  DenoiseOptions serial, parallel;
  serial.threads = 1;
  parallel.threads = 4;
  EXPECT_EQ(denoise(noisy, one.features, serial), denoise(noisy, one.features, parallel));
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

TEST(Denoiser, NoiseIsMeasuredWhereMostOfThePictureIsNoiseless) {
  // A render where the background (no hit) and an unshadowed floor are exactly constant over 7/8
  // of the picture and only the part is noisy: the noise level comes from the noisy pixels, not
  // from a median of zeros that would leave the part unfiltered.
  Image clean, noisy;
  FeatureBuffers features;
  makeScene(Side{}, Side{}, clean, features);
  noisy = test::withSeededNoise(clean, 0.1f);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (x < kSize / 2 && y < kSize / 4) continue;  // the part: a corner, noisy
      noisy.setRgb(x, y, clean.at(x, y).rgb());
      if (x >= kSize / 2) features.depth[features.index(x, y)] = std::numeric_limits<float>::infinity();
    }
  EXPECT_GT(estimateNoise(noisy, features), 0.05f);
  const Image denoised = denoise(noisy, features);
  EXPECT_LT(rootMeanSquareDifference(denoised, clean), 0.5 * rootMeanSquareDifference(noisy, clean));
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

TEST(Denoiser, KeepsAConstantImageConstantAtAnySize) {
  // Rows narrower than the filter's groups of four pixels and its widest taps (64 pixels) included.
  for (const auto& [width, height] : {std::pair{1, 1}, {3, 5}, {5, 70}, {67, 33}, {130, 6}}) {
    Image image(width, height);
    FeatureBuffers features(width, height);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        image.setRgb(x, y, Vec3{0.3f, 0.5f, 0.7f});
        const std::size_t k = features.index(x, y);
        features.albedo[k] = Vec3{0.6f, 0.6f, 0.6f};
        features.normal[k] = x % 7 < 3 ? Vec3{0, 0, 1} : Vec3{0, 1, 0};  // creases everywhere
        features.depth[k] = y % 5 == 0 ? std::numeric_limits<float>::infinity() : 10.0f + 0.1f * x;
      }
    const Image denoised = denoise(image, features);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const Rgba& p = denoised.at(x, y);
        ASSERT_NEAR(p.r, 0.3f, 1e-6f) << width << "x" << height << " at " << x << "," << y;
        ASSERT_NEAR(p.g, 0.5f, 1e-6f) << width << "x" << height << " at " << x << "," << y;
        ASSERT_NEAR(p.b, 0.7f, 1e-6f) << width << "x" << height << " at " << x << "," << y;
      }
  }
}

}  // namespace
}  // namespace lancer
