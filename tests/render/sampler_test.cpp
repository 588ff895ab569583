// Anti-aliasing: the regular n x n grid's coverage of a half-plane edge against the exact area
// fraction, adaptive supersampling against the regular grid (fewer samples, same picture), and the
// jittered and adaptive samplers bit-identical for any thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lancer/render/adaptive_sampler.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

// Area of the unit-ish pixel [x0, x1] x [y0, y1] on the side n . p >= c (one Sutherland-Hodgman
// clip, then the shoelace formula), as a fraction of the pixel's area.
double coveredFraction(double nx, double ny, double c, double x0, double y0, double x1, double y1) {
  const double square[4][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  double clipped[8][2];
  int count = 0;
  for (int i = 0; i < 4; ++i) {
    const double* a = square[i];
    const double* b = square[(i + 1) % 4];
    const double fa = nx * a[0] + ny * a[1] - c, fb = nx * b[0] + ny * b[1] - c;
    if (fa >= 0) clipped[count][0] = a[0], clipped[count++][1] = a[1];
    if ((fa >= 0) != (fb >= 0)) {
      const double t = fa / (fa - fb);
      clipped[count][0] = a[0] + t * (b[0] - a[0]);
      clipped[count++][1] = a[1] + t * (b[1] - a[1]);
    }
  }
  double twiceArea = 0;
  for (int i = 0; i < count; ++i)
    twiceArea += clipped[i][0] * clipped[(i + 1) % count][1] - clipped[(i + 1) % count][0] * clipped[i][1];
  return std::abs(twiceArea) / 2 / ((x1 - x0) * (y1 - y0));
}

constexpr int kSize = 24;
constexpr double kViewHeight = 2.0;
constexpr double kEdgeOffset = 0.0123;  // keeps the edge off pixel corners

// A white half-plane {p : p . (cos a, sin a) >= kEdgeOffset} on black, seen straight down by an
// orthographic camera, ambient light only: a pixel's value is the fraction of its samples inside.
SceneDescription halfPlaneScene(double angleDegrees, int samples, SamplerKind sampler) {
  SceneDescription d = test::topDownView(kSize, kSize, kViewHeight);
  d.render.samples = samples;
  d.render.sampler = sampler;
  d.render.background = {0, 0, 0};
  d.ambient = {1, 1, 1};
  d.materials = {test::ambientOnlyMaterial("white", {1, 1, 1})};
  d.meshes.resize(1);
  d.meshes[0].rotateDegrees = {0, 0, angleDegrees};
  return d;
}

Image renderHalfPlane(const SceneDescription& d, int threads = 0, RenderStats* stats = nullptr) {
  const Scene scene = test::sceneFromMeshes(d, {test::squareMesh(float(kEdgeOffset), -20, 20, 20, 0)});
  return test::renderScene(d, scene, AccelKind::KdTreeSah, threads, stats);
}

TEST(Sampler, RegularGridCoverageWithinHalfASampleRowOfTheExactArea) {
  // For an n x n grid each of the n rows miscounts its strip by at most half a sample (1/(2 n^2) of
  // the pixel), so the coverage is within 1/(2n) of the exact fraction: the 1/(2N) bound
  // with N the samples per axis. (Per N = n^2 samples it cannot hold: an edge along a column of
  // samples is quantised to 1/n.) The scene comes within a factor 0.4 of the bound: it is tight.
  for (int n : {1, 2, 4, 8}) {
    double worstRatio = 0;
    for (double angle : {0.0, 7.0, 30.0, 45.0, 63.0, 90.0, 124.0, 200.0}) {
      const SceneDescription d = halfPlaneScene(angle, n * n, SamplerKind::Regular);
      const Image image = renderHalfPlane(d);
      const double a = angle * std::numbers::pi / 180, nx = std::cos(a), ny = std::sin(a);
      const double pixel = kViewHeight / kSize;
      for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
          const double x0 = (x - kSize / 2) * pixel, y1 = (kSize / 2 - y) * pixel;
          const double exact = coveredFraction(nx, ny, kEdgeOffset, x0, y1 - pixel, x0 + pixel, y1);
          const double error = std::abs(image.at(x, y).r - exact);
          ASSERT_LE(error, 1.0 / (2 * n) + 1e-4)
              << "n " << n << ", angle " << angle << ", pixel " << x << "," << y;
          worstRatio = std::max(worstRatio, error * 2 * n);
        }
      }
    }
    if (n > 1) {
      EXPECT_GT(worstRatio, 0.4) << "the test scene should come near the bound for n = " << n;
    }
  }
}

TEST(Sampler, AdaptiveMaxDepthFollowsSamples) {
  EXPECT_EQ(adaptiveMaxDepth(1), 0);
  EXPECT_EQ(adaptiveMaxDepth(3), 0);
  EXPECT_EQ(adaptiveMaxDepth(4), 1);
  EXPECT_EQ(adaptiveMaxDepth(16), 2);
  EXPECT_EQ(adaptiveMaxDepth(63), 2);
  EXPECT_EQ(adaptiveMaxDepth(64), 3);
  EXPECT_EQ(adaptiveMaxDepth(1024), kMaxAdaptiveDepth);
}

TEST(Sampler, AdaptiveUsesFarFewerSamplesYetMatchesTheRegularGrid) {
  // A mostly flat image: only the pixels along the edge differ from their neighbours.
  for (double angle : {0.0, 30.0}) {
    RenderStats regularStats, adaptiveStats;
    const Image regular = renderHalfPlane(halfPlaneScene(angle, 16, SamplerKind::Regular), 0, &regularStats);
    const Image adaptive =
        renderHalfPlane(halfPlaneScene(angle, 16, SamplerKind::Adaptive), 0, &adaptiveStats);
    EXPECT_DOUBLE_EQ(regularStats.samplesPerPixel, 16.0);
    EXPECT_LT(adaptiveStats.samplesPerPixel, 4.0) << "angle " << angle;
    EXPECT_GT(adaptiveStats.samplesPerPixel, 1.0);
    double sumError = 0, worst = 0;
    int refined = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const double error = std::abs(adaptive.at(x, y).r - regular.at(x, y).r);
        sumError += error;
        worst = std::max(worst, error);
        refined += adaptive.at(x, y).r > 0 && adaptive.at(x, y).r < 1;
      }
    EXPECT_GT(refined, kSize / 2);  // edge pixels get fractional coverage, not 0 or 1
    // Both estimate each pixel's coverage to within 1/8 (4 x 4 grid, see above) where refined.
    EXPECT_LE(worst, 0.25) << "angle " << angle;
    EXPECT_LE(sumError / (kSize * kSize), 0.01) << "angle " << angle;
  }
}

TEST(Sampler, AdaptiveFlatImageTracesAboutOneSamplePerPixel) {
  // Nothing to refine: one sample per pixel corner, plus the corners tiles share (traced twice).
  SceneDescription d = halfPlaneScene(0, 64, SamplerKind::Adaptive);
  d.camera.position = Vec3d{5, 0, 5};  // the edge is out of view
  d.camera.lookAt = Vec3d{5, 0, 0};
  RenderStats stats;
  const Image image = renderHalfPlane(d, 0, &stats);
  const double expected = double((kSize + 1) * (kSize + 1)) / (kSize * kSize);  // one tile
  EXPECT_DOUBLE_EQ(stats.samplesPerPixel, expected);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) ASSERT_EQ(image.at(x, y).r, 1.0f);
}

TEST(Sampler, AdaptiveRefinesOnlyWhereCornersDifferByTheThreshold) {
  SceneDescription d = halfPlaneScene(30, 16, SamplerKind::Adaptive);
  d.materials[0].ka = {0.04f, 0.04f, 0.04f};  // an edge of contrast 0.04
  RenderStats below, above;
  d.render.adaptiveThreshold = 0.05f;
  renderHalfPlane(d, 0, &below);
  d.render.adaptiveThreshold = 0.03f;
  renderHalfPlane(d, 0, &above);
  EXPECT_DOUBLE_EQ(below.samplesPerPixel, double((kSize + 1) * (kSize + 1)) / (kSize * kSize));
  EXPECT_GT(above.samplesPerPixel, below.samplesPerPixel + 0.2);
}

// Stratified and adaptive images of a scene with edges, shadows and a mirror, for thread counts.
TEST(Sampler, StratifiedAndAdaptiveAreBitIdenticalForAnyThreadCount) {
  for (SamplerKind sampler : {SamplerKind::Stratified, SamplerKind::Adaptive}) {
    SceneDescription d = halfPlaneScene(17, 16, sampler);
    d.render.width = 70;  // tiles of 32 that do not divide the image
    d.render.height = 45;
    d.render.maxDepth = 3;
    d.camera.projection = Projection::Perspective;
    d.camera.position = Vec3d{0.4, -2.5, 3};
    d.lights = {{{0.3, -0.2, 4}, {1, 1, 1}, {1, 0, 0}}};
    Material mirror;
    mirror.name = "mirror";
    mirror.reflectivity = {0.6f, 0.6f, 0.6f};
    d.materials[0].kd = {0.5f, 0.3f, 0.2f};
    d.materials.push_back(mirror);
    d.meshes.resize(2);
    d.meshes[1].material = 1;
    d.meshes[1].rotateDegrees = {60, 0, 0};
    const Scene scene = test::sceneFromMeshes(
        d, {test::squareMesh(-2, -2, 2, 2, 0), test::squareMesh(-0.4f, -0.7f, 0.6f, 0.2f, 0.5f)});
    const Image one = test::renderScene(d, scene, AccelKind::KdTreeSah, 1);
    EXPECT_TRUE(one == test::renderScene(d, scene, AccelKind::KdTreeSah, 2));
    EXPECT_TRUE(one == test::renderScene(d, scene, AccelKind::KdTreeSah, 3));
    EXPECT_TRUE(one == test::renderScene(d, scene, AccelKind::KdTreeSah, 1));  // and across runs
    // Every pixel equals what `--pixel x,y` computes for it alone.
    const Accelerator accelerator =
        Accelerator::build(scene.geometry.positions, scene.geometry.faces, AccelKind::KdTreeSah);
    const Camera camera = makeCamera(d.camera, scene, d.render);
    const Renderer renderer(scene, accelerator, camera, d.render);
    for (int y = 0; y < d.render.height; y += 7)
      for (int x = 0; x < d.render.width; x += 5) {
        TraceCounters counters;
        std::uint64_t samples = 0;
        const Rgba alone = renderer.renderPixel(x, y, counters, samples);
        ASSERT_EQ(alone.r, one.at(x, y).r) << x << "," << y;
        ASSERT_EQ(alone.b, one.at(x, y).b) << x << "," << y;
      }
  }
}

}  // namespace
}  // namespace lancer
