// Isolines and colour bands on the gmsh-made unit square carrying the linear field x + 2 y, seen
// from straight above: the lines lie on the exact lines x + 2 y = v, keep their width in pixels, and
// bands split the surface into the asked number of colours.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/results/isolines.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

constexpr int kSide = 96;

// The unit square [0, 1]^2 filling a kSide x kSide picture (pixel (i, j) sees x = (i + 0.5) / kSide,
// y = 1 - (j + 0.5) / kSide), blue under white ambient light, with the mesh keys `meshKeys`.
SceneDescription squareScene(const std::string& meshKeys) {
  const std::string text = R"(
[render]
width = 96
height = 96
background = [0, 0, 0]
encoding = "linear"  # the map's values as they are (sRGB output lights field colours in linear space)
[camera]
projection = "orthographic"
position = [0.5, 0.5, 5]
look_at = [0.5, 0.5, 0]
up = [0, 1, 0]
view_height = 1
[ambient]
intensity = [1, 1, 1]
[material.blue]
ka = [0, 0, 1]
kd = [0, 0, 0]
ks = [0, 0, 0]
[[mesh]]
file = "../fields/node_xy_v41_bin.msh"
material = "blue"
)" + meshKeys + "\n";
  return parseScene(text, test::dataFile("render/isolines.toml"));
}

TEST(Isolines, LieOnTheExactLinesOfALinearField) {
  // Red lines of width 2 at x + 2 y = 1 and 2: the red channel is each pixel's line coverage.
  const SceneDescription description = squareScene(
      R"(isolines = { field = "temperature", values = [1.0, 2.0], color = [1, 0, 0], width = 2 })");
  const Image image = test::renderScene(description);
  for (const double value : {1.0, 2.0}) {
    int rows = 0;
    for (int j = 0; j < kSide; ++j) {
      const double y = 1 - (j + 0.5) / kSide;
      const double x = value - 2 * y;  // the exact line
      if (x < 0.1 || x > 0.9) continue;
      // The coverage-weighted centre of the line along the row, within 6 pixels of the exact one.
      const double exactColumn = x * kSide - 0.5;
      double sum = 0, weighted = 0;
      for (int i = 0; i < kSide; ++i) {
        if (std::abs(i - exactColumn) > 6) continue;
        const double coverage = image.at(i, j).r;
        sum += coverage;
        weighted += coverage * i;
      }
      ASSERT_GT(sum, 0) << "row " << j;
      EXPECT_NEAR(weighted / sum, exactColumn, 0.05) << "value " << value << " row " << j;
      // A line 2 pixels wide across the field's gradient (1, 2) crosses a row over 2 sqrt(5) pixels.
      EXPECT_NEAR(sum, 2 * std::sqrt(5.0), 0.05) << "value " << value << " row " << j;
      ++rows;
    }
    EXPECT_GT(rows, 20);
  }
  // Nothing red away from the lines.
  EXPECT_EQ(image.at(2, kSide - 3).r, 0.0f);  // x + 2 y = 0.08 there
}

TEST(Isolines, CountSpacesLinesEvenlyInsideTheRange) {
  const SceneDescription description =
      squareScene(R"(isolines = { field = "temperature", count = 3, color = [1, 0, 0], width = 1 })");
  const Scene scene = buildScene(description);
  ASSERT_TRUE(scene.isolines);
  ASSERT_EQ(scene.isolines->styles.size(), 2u);
  // The field x + 2 y runs over [0, 3] on the square: one line in the middle of each third.
  EXPECT_EQ(scene.isolines->styles[1].values, (std::vector<float>{0.5f, 1.5f, 2.5f}));
  EXPECT_EQ(evenIsoValues(0, 10, 5), (std::vector<double>{1, 3, 5, 7, 9}));
}

TEST(Isolines, LogColoursSpaceLinesEvenlyInLog) {
  // Coloured by the same field on a log scale over [0.03, 3]: `count` lines in the middle of equal
  // log intervals (0.03 * 10^0.5, 0.03 * 10^1.5); gmsh's iso-values (colorRangeEnds) include the ends.
  const SceneDescription description =
      squareScene(R"(color_by = { field = "temperature", scale = "log", range = [0.03, 3] }
isolines = { field = "temperature", count = 2, color = "map" })");
  const Scene scene = buildScene(description);
  ASSERT_TRUE(scene.isolines);
  const std::vector<float>& values = scene.isolines->styles[1].values;
  ASSERT_EQ(values.size(), 2u);
  EXPECT_NEAR(values[0], 0.03 * std::sqrt(10.0), 1e-6);
  EXPECT_NEAR(values[1], 0.3 * std::sqrt(10.0), 1e-6);
  // Each line in the colour of its place on the log scale: a quarter and three quarters of the map.
  const std::vector<Vec3>& colours = scene.isolines->styles[1].valueColors;
  ASSERT_EQ(colours.size(), 2u);
  EXPECT_LT(length(colours[0] - colorMapLookup(ColorMapKind::Viridis, 0.25f)), 1e-5f);
  EXPECT_LT(length(colours[1] - colorMapLookup(ColorMapKind::Viridis, 0.75f)), 1e-5f);
  const std::vector<double> gmsh = {0.03, 0.3, 3};  // gmsh's log getScaleValue, 3 values
  IsolineSpec spec;
  spec.field = "temperature";
  spec.count = 3;
  spec.colorRangeEnds = true;
  const ResolvedIsolines resolved = resolveIsolines(
      spec, readMsh(test::dataFile("fields/node_xy_v41_bin.msh")), {}, std::pair{0.03, 3.0}, ColorScale::Log);
  ASSERT_EQ(resolved.values.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(resolved.values[k], gmsh[k], 1e-6) << k;
  const std::vector<double> middles = logIsoValues(1, 100, 2);
  ASSERT_EQ(middles.size(), 2u);
  EXPECT_NEAR(middles[0], std::sqrt(10.0), 1e-9);
  EXPECT_NEAR(middles[1], 10 * std::sqrt(10.0), 1e-9);
}

// color = "map": each line in its value's colour, from the mesh's map over its colour range (here
// magma over [0, 3]), the surface coloured as before between the lines.
TEST(Isolines, MapColouredLinesTakeTheirValuesColour) {
  const SceneDescription description =
      squareScene(R"(color_by = { field = "temperature", map = "magma", range = [0, 3] }
isolines = { field = "temperature", values = [1.0, 2.0], color = "map", width = 3 })");
  const Image image = test::renderScene(description);
  for (const double value : {1.0, 2.0}) {
    // On the line at x = 0.5 - 2 (y - y0) (about the middle of the picture): fully covered there.
    const int j = static_cast<int>((1 - (value - 0.5) / 2) * kSide);
    const double y = 1 - (j + 0.5) / kSide;
    const int i = static_cast<int>(std::lround((value - 2 * y) * kSide - 0.5));
    const Vec3 expected = colorMapLookup(ColorMapKind::Magma, static_cast<float>(value / 3));
    EXPECT_LT(length(image.at(i, j).rgb() - expected), 1e-3f) << "value " << value;
  }
  // Between the lines the surface shows the map at the point's value: x + 2 y = 0.15 at (4, 91).
  EXPECT_LT(length(image.at(4, kSide - 5).rgb() - colorMapLookup(ColorMapKind::Magma, 0.05f)), 0.02f);
}

TEST(Bands, SplitTheSurfaceIntoTheAskedNumberOfColours) {
  const SceneDescription description =
      squareScene(R"(color_by = { field = "temperature", bands = 5, range = [0, 3] })");
  const Image image = test::renderScene(description);
  std::set<std::array<float, 3>> colours;
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i) colours.insert({image.at(i, j).r, image.at(i, j).g, image.at(i, j).b});
  EXPECT_EQ(colours.size(), 5u);
  // Each band shows the map at its middle: the pixel at (0.05, 0.05), where x + 2 y = 0.15, is in the
  // first band of [0, 0.6).
  const Vec3 first = colorMapLookup(ColorMapKind::Viridis, 0.1f);
  EXPECT_LT(length(image.at(4, kSide - 5).rgb() - first), 1e-5f);
}

TEST(Isolines, ElementDataFollowsItsMeanAtTheVertices) {
  // 3 x + y at the centroids of an 8 x 8 grid of quads (cell h = 1/8): its mean at an inner vertex is
  // 3 x + y there, so the lines cross inner edges exactly on 3 x + y = v; at the border, where fewer
  // elements meet, within a cell of it.
  const Mesh mesh = readMsh(test::dataFile("fields/element_centroids_grid_v41_ascii.msh"));
  ASSERT_EQ(mesh.fields.at(0).at, FieldAt::kElement);
  IsolineSpec spec;
  spec.field = "f";
  spec.count = 7;
  const ResolvedIsolines lines = resolveIsolines(spec, mesh);
  EXPECT_TRUE(lines.fromElementData);
  EXPECT_EQ(lines.at, FieldAt::kNode);
  ASSERT_EQ(lines.vertexValue.size(), mesh.positions.size());
  // The values spread over the element data's own range, 0.25 .. 3.75.
  ASSERT_EQ(lines.values.size(), 7u);
  EXPECT_NEAR(lines.values.front(), 0.25 + 3.5 * 0.5 / 7, 1e-5);
  EXPECT_NEAR(lines.values.back(), 0.25 + 3.5 * 6.5 / 7, 1e-5);
  const double h = 1.0 / 8, gradient = std::sqrt(10.0);
  const auto inner = [&](std::uint32_t v) {
    const Vec3d p = mesh.worldPosition(v);
    return p.x > 1e-6 && p.x < 1 - 1e-6 && p.y > 1e-6 && p.y < 1 - 1e-6;
  };
  int innerCrossings = 0, borderCrossings = 0;
  for (const MeshFace& face : mesh.faces)
    for (int c = 0; c < face.cornerCount(); ++c) {
      const std::uint32_t a = face.vertex[c], b = face.vertex[(c + 1) % face.cornerCount()];
      const double fa = lines.vertexValue[a], fb = lines.vertexValue[b];
      for (const float value : lines.values) {
        if ((fa - value) * (fb - value) > 0 || fa == fb) continue;
        const double t = (value - fa) / (fb - fa);
        const Vec3d p = mesh.worldPosition(a) * (1 - t) + mesh.worldPosition(b) * t;
        const double distance = std::abs(3 * p.x + p.y - value) / gradient;  // to the exact line
        if (inner(a) && inner(b)) {
          EXPECT_LT(distance, 1e-5) << p.x << ", " << p.y;
          ++innerCrossings;
        } else {
          EXPECT_LT(distance, h) << p.x << ", " << p.y;
          ++borderCrossings;
        }
      }
    }
  EXPECT_GT(innerCrossings, 50);
  EXPECT_GT(borderCrossings, 0);
  // Split second-order skin faces (10-node tetrahedra): a value at every vertex the faces use.
  const Mesh tet10 = readMsh(test::dataFile("fields/element_tet10_v41_bin.msh"));
  spec.field = "temperature";
  const ResolvedIsolines skin = resolveIsolines(spec, tet10);
  for (const MeshFace& face : tet10.faces)
    for (int c = 0; c < face.cornerCount(); ++c) EXPECT_FALSE(std::isnan(skin.vertexValue[face.vertex[c]]));
}

TEST(Isolines, ElementDataLinesOnFlatQuadsLieOnTheClosedForm) {
  // The grid's flat quads coloured per element, a red line at 3 x + y = 2 (the mean at the inner
  // vertices is exact): only the line is red, along its closed form, not whole faces.
  std::string text = R"(
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
[ambient]
intensity = [1, 1, 1]
[[mesh]]
file = "../fields/element_centroids_grid_v41_ascii.msh"
shading = "flat"
color_by = { field = "f", map = ["#0000ff", "#0000ff"] }
isolines = { field = "f", values = [2.0], color = [1, 0, 0], width = 2 }
)";
  const Image image = test::renderScene(parseScene(text, test::dataFile("render/isolines.toml")));
  int rows = 0;
  double red = 0;
  for (int j = 0; j < kSide; ++j) {
    const double y = 1 - (j + 0.5) / kSide, x = (2 - y) / 3;
    for (int i = 0; i < kSide; ++i) red += image.at(i, j).r;
    if (y < 0.2 || y > 0.8) continue;
    const double exactColumn = x * kSide - 0.5;
    double sum = 0, weighted = 0;
    for (int i = 0; i < kSide; ++i) {
      if (std::abs(i - exactColumn) > 6) continue;
      sum += image.at(i, j).r;
      weighted += image.at(i, j).r * i;
    }
    ASSERT_GT(sum, 0) << "row " << j;
    EXPECT_NEAR(weighted / sum, exactColumn, 0.1) << "row " << j;
    ++rows;
  }
  EXPECT_GT(rows, 50);
  // A line 2 pixels wide across the gradient (3, 1) covers 2 sqrt(10) / 3 pixels of each row.
  EXPECT_NEAR(red / kSide, 2 * std::sqrt(10.0) / 3, 0.3);
}

TEST(Isolines, ElementDataGetsANote) {
  const std::string text = R"(
[[mesh]]
file = "../fields/element_centroids_grid_v41_ascii.msh"
color_by = { field = "f" }
isolines = { field = "f", count = 5 }
)";
  const SceneDescription description = parseScene(text, test::dataFile("render/isolines.toml"));
  const Scene scene = buildScene(description);
  ASSERT_TRUE(scene.isolines.has_value());
  const std::string expected =
      "isolines.toml:5:12: warning: isolines of element data \"f\" follow its mean at "
      "each vertex (of the elements around it)";
  EXPECT_EQ(std::count_if(scene.warnings.begin(), scene.warnings.end(),
                          [&](const std::string& w) { return w.find(expected) != std::string::npos; }),
            1)
      << (scene.warnings.empty() ? "" : scene.warnings.front());
}

TEST(IsolinesBadInput, UnknownFieldCountsAndKeys) {
  const SceneDescription unknown = squareScene(R"(isolines = { field = "temprature" })");
  const std::string message = test::messageOf([&] { buildScene(unknown); });
  EXPECT_NE(message.find("isolines field \"temprature\" is not in"), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean 'temperature'?"), std::string::npos) << message;
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\nisolines = { field = \"T\", count = 0 }\n",
                                 "scene.toml:3:");
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\nisolines = { field = \"T\", count = 0 }\n",
                                 "mesh[0].isolines.count");
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\nisolines = { field = \"T\", count = 100000 }\n",
                                 "mesh[0].isolines.count");
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\nisolines = { count = 3 }\n", "field");
  test::expectSceneErrorContains(
      "[[mesh]]\nfile = \"a.msh\"\nisolines = { field = \"T\", color = \"red\" }\n",
      "mesh[0].isolines.color must be [r, g, b] or \"map\"");
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\nisolines = { field = \"T\", values = [] }\n",
                                 "must be an array of 1 to 1000 numbers");
  test::expectSceneErrorContains(
      "[[mesh]]\nfile = \"a.msh\"\nisolines = { field = \"T\", values = [1, \"a\"] }\n",
      "must hold finite numbers");
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\nisolines = { field = \"T\", width = 0 }\n",
                                 "mesh[0].isolines.width");
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\nisolines = 3\n", "must be a table");
  test::expectSceneErrorContains(
      "[[mesh]]\nfile = \"a.msh\"\ncolor_by = { field = \"T\", legend = \"left\" }\n", "scene.toml:3:");
  test::expectSceneErrorContains(
      "[[mesh]]\nfile = \"a.msh\"\ncolor_by = { field = \"T\", legend = \"left\" }\n", "right");
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\ncolor_by = { field = \"T\", bands = 0 }\n",
                                 "mesh[0].color_by.bands");
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\ncolor_by = { field = \"T\", bands = 1000 }\n",
                                 "mesh[0].color_by.bands");
}

}  // namespace
}  // namespace lancer
