// The denoiser's features from the path tracer's own samples (FeatureIntegrator) against the separate
// primary-ray pass (Renderer::renderFeatures): the same surfaces, the same values wherever a pixel sees
// one surface whole, and a radiance that does not change for being watched.
#include <gtest/gtest.h>

#include <cmath>

#include "lancer/render/renderer.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

// Two squares, the upper one shadowing the lower, in two colours, under the path tracer.
struct TwoSquares {
  SceneDescription description;
  Scene scene;
  Accelerator accelerator;
  Camera camera;

  explicit TwoSquares(IntegratorKind integrator)
      : description(makeDescription(integrator)),
        scene(makeScene(description)),
        accelerator(Accelerator::build(scene.geometry.positions, scene.geometry.faces, AccelKind::KdTreeSah)),
        camera(makeCamera(description.camera, scene, description.render)) {}

  static SceneDescription makeDescription(IntegratorKind integrator) {
    SceneDescription description = test::flatLitOnBlue(test::topDownView(48, 48, 4.0), {1.5, 1.0, 6.0});
    description.render.integrator = integrator;
    description.render.samples = 16;
    description.materials = {test::matteMaterial("grey", {0.2f, 0.2f, 0.2f}, {0.7f, 0.7f, 0.7f}),
                             test::matteMaterial("warm", {0.2f, 0.15f, 0.1f}, {0.8f, 0.5f, 0.3f})};
    description.meshes.resize(2);
    description.meshes[1].material = 1;
    return description;
  }
  static Scene makeScene(const SceneDescription& description) {
    std::vector<Mesh> meshes;
    meshes.push_back(test::squareMesh(-1.8f, -1.8f, 1.8f, 1.8f, 0.0f));
    meshes.push_back(test::squareMesh(-0.6f, -0.6f, 0.6f, 0.6f, 1.0f));
    return test::sceneFromMeshes(description, std::move(meshes));
  }
  Renderer renderer() const { return Renderer(scene, accelerator, camera, description.render); }
};

// The image with the features of its samples.
Image renderWithFeatures(const Renderer& renderer, FeatureBuffers& features, int threads) {
  RenderOptions options;
  options.threads = threads;
  options.features = &features;
  return renderer.renderImage(options);
}

TEST(SampleFeatures, OnlyThePathTracerReportsThem) {
  EXPECT_TRUE(TwoSquares(IntegratorKind::Path).renderer().featuresFromSamples());
  EXPECT_FALSE(TwoSquares(IntegratorKind::Whitted).renderer().featuresFromSamples());
  EXPECT_FALSE(TwoSquares(IntegratorKind::AmbientOcclusion).renderer().featuresFromSamples());
}

TEST(SampleFeatures, EqualTheFeaturePassWhereAPixelSeesOneSurface) {
  const TwoSquares scene(IntegratorKind::Path);
  const Renderer renderer = scene.renderer();
  FeatureBuffers fromSamples(48, 48);
  renderWithFeatures(renderer, fromSamples, 0);
  const FeatureBuffers pass = renderer.renderFeatures(0);
  int interior = 0;
  double albedoError = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x) {
      const std::size_t k = pass.index(x, y);
      albedoError += std::abs(fromSamples.albedo[k].y - pass.albedo[k].y);
      // A pixel whose neighbours all see what it sees lies inside one surface (or the background).
      bool inside = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int qx = std::clamp(x + dx, 0, 47), qy = std::clamp(y + dy, 0, 47);
          const std::size_t q = pass.index(qx, qy);
          inside = inside && pass.albedo[q] == pass.albedo[k] && (pass.depth[q] == pass.depth[k]);
        }
      if (!inside) continue;
      ++interior;
      EXPECT_NEAR(fromSamples.albedo[k].x, pass.albedo[k].x, 1e-5f) << x << "," << y;
      EXPECT_NEAR(fromSamples.albedo[k].y, pass.albedo[k].y, 1e-5f) << x << "," << y;
      EXPECT_NEAR(fromSamples.normal[k].z, pass.normal[k].z, 1e-5f) << x << "," << y;
      if (std::isinf(pass.depth[k]))
        EXPECT_TRUE(std::isinf(fromSamples.depth[k])) << x << "," << y;
      else
        EXPECT_NEAR(fromSamples.depth[k], pass.depth[k], 1e-4f) << x << "," << y;
    }
  EXPECT_GT(interior, 48 * 48 * 2 / 3);
  // At the edges the two sample different points of the pixel: close on average all the same.
  EXPECT_LT(albedoError / (48 * 48), 0.01);
}

TEST(SampleFeatures, LeaveTheRadianceAsItIsAndTheSameForAnyThreadCount) {
  const TwoSquares scene(IntegratorKind::Path);
  const Renderer renderer = scene.renderer();
  RenderOptions plain;
  plain.threads = 1;
  const Image unwatched = renderer.renderImage(plain);
  FeatureBuffers one(48, 48), two(48, 48);
  EXPECT_EQ(renderWithFeatures(renderer, one, 1), unwatched);
  EXPECT_EQ(renderWithFeatures(renderer, two, 2), unwatched);
  EXPECT_EQ(one.albedo, two.albedo);
  EXPECT_EQ(one.normal, two.normal);
  EXPECT_EQ(one.depth, two.depth);
  EXPECT_EQ(one.variance, two.variance);
}

TEST(SampleFeatures, CarryEachPixelsVarianceWhereTheSamplesKnowIt) {
  const TwoSquares scene(IntegratorKind::Path);
  const Renderer renderer = scene.renderer();
  FeatureBuffers fromSamples(48, 48);
  renderWithFeatures(renderer, fromSamples, 0);
  const FeatureBuffers pass = renderer.renderFeatures(0);
  // The background is one colour for every sample: no spread. The lit squares' soft shadows and
  // sampled lights spread their samples: some variance, within reason for values below a few units.
  EXPECT_EQ(fromSamples.variance[fromSamples.index(0, 0)], 0.0f);
  int spread = 0;
  for (const float v : fromSamples.variance) {
    EXPECT_GE(v, 0.0f);
    EXPECT_LT(v, 1.0f);
    spread += v > 0.0f;
  }
  EXPECT_GT(spread, 48 * 48 / 4);
  // The primary-ray pass has no samples' spread to give: unknown everywhere.
  for (const float v : pass.variance) EXPECT_LT(v, 0.0f);
}

TEST(SampleFeatures, TheFinalRenderDenoisesWithTheSamplesFeatures) {
  TwoSquares scene(IntegratorKind::Path);
  scene.description.render.denoise = true;
  const Renderer renderer = scene.renderer();
  FeatureBuffers given, fromSamples(48, 48);
  RenderOptions options;
  options.threads = 2;
  renderer.renderFinal(options, nullptr, &given);
  renderWithFeatures(renderer, fromSamples, 2);
  EXPECT_EQ(given.albedo, fromSamples.albedo);
  EXPECT_EQ(given.depth, fromSamples.depth);
}

}  // namespace
}  // namespace lancer
