// Every annotation in every integrator: isolines are painted by the path and AO integrators as by
// the Whitted tracer (on the surface's albedo), and the undeformed shape drawn as edges is lines on
// a surface every integrator sees through (under --look studio it was an opaque grey slab).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "lancer/image/image_io.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"
#include "support/test_images.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

constexpr int kSide = 96;

// The unit square [0, 1]^2 with the field x + 2 y filling a kSide x kSide picture, blue and unlit
// (its colour as it is in every integrator), with red isolines 2 pixels wide at x + 2 y = 1 and 2.
SceneDescription squareWithIsolines(IntegratorKind integrator) {
  SceneDescription description = parseScene(R"(
[render]
width = 96
height = 96
background = [0, 0, 0]
encoding = "linear"
[camera]
projection = "orthographic"
position = [0.5, 0.5, 5]
look_at = [0.5, 0.5, 0]
up = [0, 1, 0]
view_height = 1
[material.blue]
ka = [0, 0, 1]
kd = [0, 0, 1]
ks = [0, 0, 0]
[[mesh]]
file = "../fields/node_xy_v41_bin.msh"
material = "blue"
shading = "unlit"
isolines = { field = "temperature", values = [1.0, 2.0], color = [1, 0, 0], width = 2 }
)",
                                            test::dataFile("render/isolines.toml"));
  description.render.integrator = integrator;
  // Path and AO sample each pixel at points of their own, not its centre: 16 of them average to the
  // pixel's coverage as the Whitted tracer's one sample at the centre computes it.
  if (integrator != IntegratorKind::Whitted) description.render.samples = 16;
  return description;
}

// Each row of the picture crossed by a line holds 2 sqrt(5) pixels of it (a line 2 pixels wide
// across the gradient (1, 2)), in the red channel; `rows` counts the rows checked.
void expectLinesOfWidthTwo(const Image& image, const char* integrator) {
  for (const double value : {1.0, 2.0}) {
    int rows = 0;
    for (int j = 0; j < kSide; ++j) {
      const double y = 1 - (j + 0.5) / kSide;
      const double x = value - 2 * y;
      if (x < 0.1 || x > 0.9) continue;
      const double exactColumn = x * kSide - 0.5;
      double sum = 0;
      for (int i = 0; i < kSide; ++i)
        if (std::abs(i - exactColumn) <= 6) sum += image.at(i, j).r;
      EXPECT_NEAR(sum, 2 * std::sqrt(5.0), 0.25) << integrator << ": value " << value << " row " << j;
      ++rows;
    }
    EXPECT_GT(rows, 20) << integrator;
  }
  EXPECT_EQ(image.at(2, kSide - 3).r, 0.0f) << integrator;  // far from both lines
  EXPECT_EQ(image.at(2, kSide - 3).b, 1.0f) << integrator;  // the surface's colour as it is
}

TEST(AnnotationsInIntegrators, IsolinesInTheWhittedTracer) {
  expectLinesOfWidthTwo(test::renderScene(squareWithIsolines(IntegratorKind::Whitted)), "whitted");
}

TEST(AnnotationsInIntegrators, IsolinesInThePathTracer) {
  expectLinesOfWidthTwo(test::renderScene(squareWithIsolines(IntegratorKind::Path)), "path");
}

TEST(AnnotationsInIntegrators, IsolinesInAmbientOcclusion) {
  expectLinesOfWidthTwo(test::renderScene(squareWithIsolines(IntegratorKind::AmbientOcclusion)), "ao");
}

// `lancer render` of the gmsh-made cantilever bent at step 3, with and without its undeformed shape
// in edges, with `options`: the pixels that differ by more than 8/255 with their 8 neighbours (inside
// an area that changed, not on a line).
int undeformedEdgesArea(const std::string& options) {
  const test::ScratchFolder folder;
  const std::string common = test::quoted(test::dataFile("results/cantilever.msh")) +
                             " --warp displacement:1 --color-by stress:von_mises --step 3 --width 320 "
                             "--height 180 -q " +
                             options;
  const std::string plain = folder.file("plain.png"), edges = folder.file("edges.png");
  const test::CommandResult a = test::runCli("render " + common + " -o " + test::quoted(plain) + " 2>&1");
  const test::CommandResult b =
      test::runCli("render " + common + " --undeformed edges -o " + test::quoted(edges) + " 2>&1");
  EXPECT_EQ(a.exitCode, 0) << a.output;
  EXPECT_EQ(b.exitCode, 0) << b.output;
  const Image without = readPng(plain), with = readPng(edges);
  auto differs = [&](int x, int y) {
    return maxComponent(abs(with.at(x, y).rgb() - without.at(x, y).rgb())) > 8.0f / 255.0f;
  };
  int area = 0;
  for (int y = 1; y + 1 < with.height(); ++y)
    for (int x = 1; x + 1 < with.width(); ++x) {
      bool all = true;
      for (int dy = -1; dy <= 1 && all; ++dy)
        for (int dx = -1; dx <= 1 && all; ++dx) all = differs(x + dx, y + dy);
      area += all ? 1 : 0;
    }
  return area;
}

// The box's 12 feature edges, about 1.5 pixels wide, leave a few such pixels where lines meet; the
// opaque slab the studio look drew left 557.
TEST(AnnotationsInIntegrators, UndeformedEdgesAreLinesUnderTheStudioLook) {
  EXPECT_LT(undeformedEdgesArea("--look studio --samples 16"), 60);
}

TEST(AnnotationsInIntegrators, UndeformedEdgesAreLinesInAmbientOcclusion) {
  EXPECT_LT(undeformedEdgesArea("--integrator ao --samples 16"), 60);
}

TEST(AnnotationsInIntegrators, UndeformedEdgesAreLinesInTheWhittedTracer) {
  EXPECT_LT(undeformedEdgesArea(""), 60);
}

}  // namespace
}  // namespace lancer
