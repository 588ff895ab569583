// Emissive mesh faces as lights: a floor lit only by an emissive square matches the closed-form
// irradiance of a rectangle (Howell's catalogue, C-11: a differential area to a parallel rectangle),
// and the same scene with a `rect` light of equal power; next-event estimation leaves far less noise
// than the material's own (cosine-weighted) samples would, whose variance is known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "lancer/render/emissive_faces.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kWidth = 32, kHeight = 8;
constexpr double kCentre = 1.1, kWorldWidth = 1.6;  // the floor from x = 0.3 to 1.9, beside the lamp
constexpr double kLampHeight = 1.0, kLampHalf = 0.25, kAlbedo = 0.5, kRadiance = 4.0;

// The view of the floor beside the lamp, path traced, direct light only.
SceneDescription floorBesideLamp(int samples) {
  SceneDescription d = test::orthographicView(kWidth, kHeight, {kCentre, 0, 5}, {kCentre, 0, 0},
                                              kWorldWidth * kHeight / kWidth);
  d.render.integrator = IntegratorKind::Path;
  d.render.samples = samples;
  d.render.maxBounces = 1;
  d.ambient = {0, 0, 0};
  d.materials = {test::matteMaterial("floor", {0, 0, 0}, {0.5f, 0.5f, 0.5f}),
                 test::matteMaterial("lamp", {0, 0, 0}, {0, 0, 0})};
  for (Material& m : d.materials) m.ks = {0, 0, 0};
  d.materials[1].emission = {4, 4, 4};
  return d;
}

Image renderWithLamp(int samples) {
  SceneDescription d = floorBesideLamp(samples);
  d.meshes.resize(2);
  d.meshes[1].material = 1;
  return test::renderMeshes(d, {test::squareMesh(-2, -2, 4, 2, 0),
                                test::squareMesh(-kLampHalf, -kLampHalf, kLampHalf, kLampHalf, kLampHeight)});
}

// The floor's point behind pixel (x, y).
void floorPoint(int x, int y, double& wx, double& wy) {
  wx = kCentre + ((x + 0.5) / kWidth - 0.5) * kWorldWidth;
  wy = (0.5 - (y + 0.5) / kHeight) * kWorldWidth * kHeight / kWidth;
}

// Irradiance over radiance from a rectangle [x0, x1] x [y0, y1] at height h above a point at the origin,
// parallel to the floor: pi times the form factor, summed over the corners with signs.
double rectangleIrradiance(double x0, double x1, double y0, double y1, double h) {
  auto corner = [h](double x, double y) {
    const double sx = std::sqrt(x * x + h * h), sy = std::sqrt(y * y + h * h);
    return 0.5 * (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy));
  };
  return corner(x1, y1) - corner(x0, y1) - corner(x1, y0) + corner(x0, y0);
}

double expectedPixel(int x, int y) {
  double wx, wy;
  floorPoint(x, y, wx, wy);
  const double e =
      rectangleIrradiance(-kLampHalf - wx, kLampHalf - wx, -kLampHalf - wy, kLampHalf - wy, kLampHeight);
  return kAlbedo / kPi * kRadiance * e;
}

TEST(EmissiveFaces, FloorMatchesTheClosedFormIrradianceOfTheRectangle) {
  // Sanity of the oracle: a rectangle far larger than its height gives E = pi L over its middle.
  EXPECT_NEAR(rectangleIrradiance(-1e4, 1e4, -1e4, 1e4, 1), kPi, 1e-3);
  const Image image = renderWithLamp(64);
  for (int x = 0; x < kWidth; ++x) {
    double got = 0, expected = 0;
    for (int y = 0; y < kHeight; ++y) {
      got += image.at(x, y).g / kHeight;
      expected += expectedPixel(x, y) / kHeight;
    }
    EXPECT_NEAR(got, expected, 0.01 * expected + 1e-4) << "column " << x;
  }
}

TEST(EmissiveFaces, EqualsARectLightOfEqualPower) {
  SceneDescription d = floorBesideLamp(64);
  PointLight rect;
  rect.type = LightType::Rect;
  rect.position = {0, 0, kLampHeight};
  rect.direction = {0, 0, -1};
  rect.width = rect.height = 2 * kLampHalf;
  // A rect's radiance is pi I / area.
  const float intensity = static_cast<float>(kRadiance * rect.width * rect.height / kPi);
  rect.intensity = {intensity, intensity, intensity};
  d.lights = {rect};
  d.meshes.resize(1);
  const Image lit = test::renderMeshes(d, {test::squareMesh(-2, -2, 4, 2, 0)});
  const Image lamp = renderWithLamp(64);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      EXPECT_NEAR(lamp.at(x, y).r, lit.at(x, y).r, 0.02 * lit.at(x, y).r + 2e-4) << x << "," << y;
}

TEST(EmissiveFaces, NextEventEstimationLeavesFarLessNoiseThanMaterialSamples) {
  // With the material's samples alone each sample is kd L (a cosine-weighted direction that meets the
  // lamp, probability F = E / pi) or 0: per pixel of n samples a standard deviation of
  // kd L sqrt(F (1 - F) / n). Measured: the pixels' error against the closed form at n = 16.
  constexpr int kSamples = 16;
  const Image image = renderWithLamp(kSamples);
  double squaredError = 0, materialVariance = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const double expected = expectedPixel(x, y);
      const double f = expected / (kAlbedo / kPi * kRadiance) / kPi;
      squaredError += std::pow(image.at(x, y).g - expected, 2);
      materialVariance += std::pow(kAlbedo * kRadiance, 2) * f * (1 - f) / kSamples;
    }
  const double rmsError = std::sqrt(squaredError / (kWidth * kHeight));
  const double materialRms = std::sqrt(materialVariance / (kWidth * kHeight));
  EXPECT_LT(rmsError, 0.1 * materialRms) << "rms error " << rmsError << ", material sampling " << materialRms;
}

TEST(EmissiveFaces, PdfAgreesWithTheSamplesItGives) {
  SceneDescription d = floorBesideLamp(1);
  d.meshes.resize(2);
  d.meshes[1].material = 1;
  const Scene scene = test::sceneFromMeshes(
      d, {test::squareMesh(-2, -2, 4, 2, 0), test::squareMesh(-0.25f, -0.25f, 0.25f, 0.25f, 1)});
  const EmissiveFaces lamps(scene);
  ASSERT_EQ(lamps.triangleCount(), 2u);  // the lamp's quad as two triangles, the floor not at all
  const Vec3 point{1, 0.2f, 0};
  for (float u : {0.1f, 0.6f, 0.9f}) {
    LightSample sample;
    ASSERT_TRUE(lamps.sample(point, u, 0.3f, sample));
    const float distance = length(sample.target - point);
    // The lamp is face 1 of the scene; its area 0.25, so the density per area is 4.
    EXPECT_NEAR(sample.pdf, lamps.pdf(1, distance, std::abs(sample.direction.z)), 1e-3f * sample.pdf);
    EXPECT_NEAR(sample.pdf, 4.0f * distance * distance / std::abs(sample.direction.z), 1e-3f * sample.pdf);
    EXPECT_FLOAT_EQ(lamps.pdf(0, distance, 0.5f), 0.0f);
  }
}

}  // namespace
}  // namespace lancer
