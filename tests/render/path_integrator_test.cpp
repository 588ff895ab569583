// The path and AO integrators against closed forms: the white furnace (a diffuse sphere in a
// uniform environment shows kd L everywhere), direct light equal to the Whitted model's diffuse
// term, a sun's penumbra on a plane against the visible fraction of its disc, a small sphere light
// against the point light it approaches, a constant HDR map against the uniform environment, and
// the same bytes for any thread count and band split.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "lancer/image/exr_io.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

constexpr double kPi = 3.14159265358979323846;

SceneDescription sphereInEnvironment(Vec3 radiance, int samples) {
  SceneDescription d = test::topDownView(48, 48, 2.4);
  d.render.integrator = IntegratorKind::Path;
  d.render.samples = samples;
  d.render.maxBounces = 6;
  d.ambient = {0, 0, 0};
  d.materials = {test::matteMaterial("matte", {0, 0, 0}, {0.6f, 0.6f, 0.6f})};
  d.materials[0].ks = {0, 0, 0};
  EnvironmentSettings environment;
  environment.color = radiance;
  d.environment = environment;
  d.meshes.resize(1);
  d.meshes[0].smoothAngleDegrees = 80;
  return d;
}

Image renderSphere(const SceneDescription& d, int threads = 0) {
  const Scene scene = test::sceneFromMeshes(d, {readMsh(LANCER_TEST_DATA_DIR "/render/sphere_fine.msh")});
  return test::renderScene(d, scene, AccelKind::KdTreeSah, threads);
}

// Calls `check(pixel, x, y)` for the pixels well inside the sphere's silhouette.
template <typename Check>
int forSpherePixels(const Image& image, double viewHeight, Check check) {
  int count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const double wx = ((x + 0.5) / image.width() - 0.5) * viewHeight;
      const double wy = (0.5 - (y + 0.5) / image.height()) * viewHeight;
      if (wx * wx + wy * wy > 0.9 * 0.9) continue;
      check(image.at(x, y), wx, wy);
      ++count;
    }
  return count;
}

TEST(PathIntegrator, WhiteFurnaceGivesAlbedoTimesRadiance) {
  const Image image = renderSphere(sphereInEnvironment({0.8f, 0.8f, 0.8f}, 8));
  const int count = forSpherePixels(image, 2.4, [](const Rgba& pixel, double, double) {
    EXPECT_NEAR(pixel.r, 0.6 * 0.8, 0.01);
    EXPECT_NEAR(pixel.b, 0.6 * 0.8, 0.01);
  });
  EXPECT_GT(count, 1000);
}

TEST(PathIntegrator, ConstantHdrMapEqualsTheUniformEnvironment) {
  // A 16 x 8 map, every pixel RGBE (191, 191, 191, 128): (191 + 0.5) / 256 in each channel.
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "lancer_constant_map.hdr";
  {
    std::ofstream out(file, std::ios::binary);
    out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 16\n";
    for (int i = 0; i < 16 * 8; ++i) out << '\xBF' << '\xBF' << '\xBF' << '\x80';
  }
  SceneDescription d = sphereInEnvironment({1, 1, 1}, 16);
  d.environment->kind = EnvironmentSettings::Kind::Map;
  d.environment->map = file.string();
  d.environment->rotationDegrees = 30;
  const double radiance = (191 + 0.5) / 256;
  double sum = 0;
  const int count = forSpherePixels(renderSphere(d), 2.4, [&](const Rgba& pixel, double, double) {
    EXPECT_NEAR(pixel.g, 0.6 * radiance, 0.1);  // one pixel: 16 samples of light and material sampling
    sum += pixel.g;
  });
  EXPECT_NEAR(sum / count, 0.6 * radiance, 0.005);
  std::filesystem::remove(file);
}

TEST(PathIntegrator, ConstantExrMapEqualsTheUniformEnvironment) {
  if (!exrSupported()) GTEST_SKIP() << "built without OpenEXR";
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "lancer_constant_map.exr";
  Image map(16, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) map.at(x, y) = Rgba{0.7f, 0.7f, 0.7f, 1.0f};
  writeExr(file.string(), map);
  SceneDescription d = sphereInEnvironment({1, 1, 1}, 16);
  d.environment->kind = EnvironmentSettings::Kind::Map;
  d.environment->map = file.string();
  d.environment->rotationDegrees = -50;
  double sum = 0;
  const int count = forSpherePixels(renderSphere(d), 2.4, [&](const Rgba& pixel, double, double) {
    EXPECT_NEAR(pixel.b, 0.6 * 0.7, 0.1);
    sum += pixel.b;
  });
  EXPECT_NEAR(sum / count, 0.6 * 0.7, 0.005);
  std::filesystem::remove(file);
}

TEST(PathIntegrator, DirectLightEqualsTheWhittedDiffuseTerm) {
  SceneDescription d = sphereInEnvironment({0, 0, 0}, 16);
  d.environment.reset();
  PointLight light;
  light.position = {3.0, 4.0, 6.0};
  light.intensity = {0.9f, 0.8f, 0.7f};
  d.lights = {light};
  d.render.maxBounces = 1;
  const Image path = renderSphere(d);
  d.render.integrator = IntegratorKind::Whitted;
  const Image whitted = renderSphere(d);
  forSpherePixels(path, 2.4, [&](const Rgba& pixel, double wx, double wy) {
    const int x = static_cast<int>((wx / 2.4 + 0.5) * 48), y = static_cast<int>((0.5 - wy / 2.4) * 48);
    EXPECT_NEAR(pixel.r, whitted.at(x, y).r, 3.0 / 255) << x << "," << y;
    EXPECT_NEAR(pixel.b, whitted.at(x, y).b, 3.0 / 255) << x << "," << y;
  });
}

// The share of a disc of angular radius r on one side of a line at signed distance a from its centre.
double discFraction(double a, double r) {
  if (a <= -r) return 0;
  if (a >= r) return 1;
  return 0.5 + (a * std::sqrt(r * r - a * a) + r * r * std::asin(a / r)) / (kPi * r * r);
}

TEST(PathIntegrator, SunPenumbraMatchesTheVisibleShareOfItsDisc) {
  // A floor at z = 0 and a roof over x < 0 at z = 1; the sun 45 degrees off the zenith towards -x,
  // 5 degrees wide. From (x, 0, 0) the roof's edge is atan(x) off the zenith: the sun shows the part
  // of its disc below that line. Columns of x in [0.2, 1.8], averaged over their rows.
  constexpr int kWidth = 128, kHeight = 4;
  constexpr double kWorldWidth = 1.6, kAngle = 5.0;
  SceneDescription d =
      test::orthographicView(kWidth, kHeight, {1, 0, 5}, {1, 0, 0}, kWorldWidth * kHeight / kWidth);
  d.render.integrator = IntegratorKind::Path;
  d.render.samples = 64;
  d.render.maxBounces = 1;
  d.materials = {test::matteMaterial("matte", {0, 0, 0}, {0.5f, 0.5f, 0.5f})};
  d.materials[0].ks = {0, 0, 0};
  PointLight sun;
  sun.type = LightType::Sun;
  sun.direction = normalize(Vec3d{-1, 0, 1});
  sun.angleDegrees = kAngle;
  sun.intensity = {1, 1, 1};
  d.lights = {sun};
  d.meshes.resize(2);
  const Image image =
      test::renderMeshes(d, {test::squareMesh(-10, -10, 10, 10, 0), test::squareMesh(-10, -10, 0, 10, 1)});
  const double r = 0.5 * kAngle * kPi / 180;
  for (int x = 0; x < kWidth; ++x) {
    double expected = 0, got = 0;
    constexpr int kSub = 16;
    for (int s = 0; s < kSub; ++s) {
      const double wx = 1 + ((x + (s + 0.5) / kSub) / kWidth - 0.5) * kWorldWidth;
      expected += 0.5 * std::cos(kPi / 4) * discFraction(std::atan(wx) - kPi / 4, r) / kSub;
    }
    for (int y = 0; y < kHeight; ++y) got += image.at(x, y).g / kHeight;
    EXPECT_NEAR(got, expected, 0.01) << "column " << x;
  }
}

TEST(PathIntegrator, SmallSphereLightIsThePointLightItApproaches) {
  SceneDescription d = test::topDownView(16, 16, 0.5);
  d.render.integrator = IntegratorKind::Path;
  d.render.samples = 16;
  d.render.maxBounces = 1;
  d.materials = {test::matteMaterial("matte", {0, 0, 0}, {0.5f, 0.5f, 0.5f})};
  d.materials[0].ks = {0, 0, 0};
  PointLight bulb;
  bulb.type = LightType::Sphere;
  bulb.position = {0, 0, 4};
  bulb.radius = 0.05;
  bulb.intensity = {16, 16, 16};  // from 4 units: 16 / 4^2 = 1
  d.lights = {bulb};
  d.meshes.resize(1);
  const Image image = test::renderMeshes(d, {test::squareMesh(-1, -1, 1, 1, 0)});
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const double wx = ((x + 0.5) / 16 - 0.5) * 0.5, wy = (0.5 - (y + 0.5) / 16) * 0.5;
      const double d2 = wx * wx + wy * wy + 16;
      EXPECT_NEAR(image.at(x, y).r, 0.5 * 16 / d2 * (4 / std::sqrt(d2)), 0.005);
    }
}

TEST(PathIntegrator, DiskLightGivesTheClosedFormIrradianceOnItsAxis) {
  // A disk of radius r at height h facing down: radiance L = pi I / (pi r^2) = I / r^2, and on its
  // axis E = pi L r^2 / (r^2 + h^2), so a Lambertian face shows kd I / (r^2 + h^2) (not the far-field
  // kd I / h^2 of the point it approaches). The pixels are within 0.02 of the axis.
  SceneDescription d = test::topDownView(4, 4, 0.02);
  d.render.integrator = IntegratorKind::Path;
  d.render.samples = 256;
  d.render.maxBounces = 1;
  d.materials = {test::matteMaterial("matte", {0, 0, 0}, {0.5f, 0.5f, 0.5f})};
  d.materials[0].ks = {0, 0, 0};
  PointLight disk;
  disk.type = LightType::Disk;
  disk.position = {0, 0, 1};
  disk.direction = {0, 0, -1};
  disk.radius = 0.5;
  disk.intensity = {1, 1, 1};
  d.lights = {disk};
  d.meshes.resize(1);
  const Image image = test::renderMeshes(d, {test::squareMesh(-1, -1, 1, 1, 0)});
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) EXPECT_NEAR(image.at(x, y).r, 0.5 / (0.25 + 1.0), 0.004) << x << "," << y;
}

TEST(AoIntegrator, OpenPlaneShowsItsAlbedo) {
  SceneDescription d = test::topDownView(8, 8, 1.0);
  d.render.integrator = IntegratorKind::AmbientOcclusion;
  d.render.samples = 4;
  d.render.aoDistance = 0.5f;
  d.materials = {test::matteMaterial("matte", {0, 0, 0}, {0.4f, 0.5f, 0.6f})};
  d.meshes.resize(1);
  const Image open = test::renderMeshes(d, {test::squareMesh(-1, -1, 1, 1, 0)});
  EXPECT_FLOAT_EQ(open.at(3, 3).g, 0.5f);
  EXPECT_FLOAT_EQ(open.at(3, 3).b, 0.6f);
}

TEST(PathIntegrator, SameBytesForAnyThreadCountAndBandSplit) {
  SceneDescription d = sphereInEnvironment({0.5f, 0.6f, 0.7f}, 8);
  d.render.width = 40;
  d.render.height = 70;
  d.render.noise = 0.05f;
  PointLight sun;
  sun.type = LightType::Sun;
  sun.direction = normalize(Vec3d{1, 1, 1});
  d.lights = {sun};
  const Scene scene = test::sceneFromMeshes(d, {readMsh(LANCER_TEST_DATA_DIR "/render/sphere_fine.msh")});
  const Image one = test::renderScene(d, scene, AccelKind::KdTreeSah, 1);
  const Image three = test::renderScene(d, scene, AccelKind::KdTreeSah, 3);
  const Accelerator accelerator =
      Accelerator::build(scene.geometry.positions, scene.geometry.faces, AccelKind::KdTreeSah);
  const Camera camera = makeCamera(d.camera, scene, d.render);
  const Image rows =
      Renderer(scene, accelerator, camera, d.render).renderRows(BandRange{1, 1}, RenderOptions{});
  for (int y = 0; y < d.render.height; ++y)
    for (int x = 0; x < d.render.width; ++x) {
      ASSERT_EQ(one.at(x, y), three.at(x, y)) << x << "," << y;
      if (y >= 32 && y < 64) {
        ASSERT_EQ(one.at(x, y), rows.at(x, y - 32)) << x << "," << y;
      }
    }
}

TEST(PathIntegrator, NonFinitePixelsAreAnErrorNotAPicture) {
  SceneDescription d = sphereInEnvironment({0, 0, 0}, 1);
  d.environment.reset();
  // A point light whose intensity is a float but whose light on the sphere is not (a sun as bright is
  // refused when the scene is built: its radiance overflows).
  PointLight light;
  light.position = {0, 0, 3};
  light.intensity = {3e38f, 3e38f, 3e38f};
  d.lights = {light};
  try {
    renderSphere(d);
    FAIL() << "no error";
  } catch (const NonFiniteRenderError& error) {  // the Whitted tracer's error: exit code 2 in the CLI
    EXPECT_NE(std::string(error.what()).find("came out non-finite (rgb "), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace lancer
