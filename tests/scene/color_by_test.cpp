// color_by: reading the scene key and resolving it against a gmsh-made mesh with the field x + 2 y
// (tests/data/fields/): normalised values, ranges, and the errors for unknown fields and steps.
#include "lancer/scene/results/color_by.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "lancer/mesh/msh_reader.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

std::optional<ColorBy> parse(const std::string& text) {
  const toml::table root = toml::parse(std::string_view(text), std::string_view("scene.toml"));
  const TomlTableReader reader(root, "mesh[0]", "scene.toml", SceneTable::Mesh);
  return readColorBy("scene.toml", reader);
}

std::string parseError(const std::string& text) {
  return test::messageOf([&] { parse(text); });
}

Mesh fieldMesh() { return readMsh(test::dataFile("fields/node_xy_v41_ascii.msh")); }

TEST(ColorByTest, ReadsAllKeys) {
  const auto spec =
      parse("color_by = { field = \"temperature\", step = 2, map = \"magma\", range = [-1, 4.5] }");
  ASSERT_TRUE(spec);
  EXPECT_EQ(spec->field, "temperature");
  EXPECT_EQ(spec->step, 2);
  EXPECT_EQ(spec->map, ColorMapKind::Magma);
  ASSERT_TRUE(spec->range);
  EXPECT_EQ(spec->range->first, -1.0);
  EXPECT_EQ(spec->range->second, 4.5);
  EXPECT_EQ(spec->where.line, 1);
}

TEST(ColorByTest, DefaultsAndAbsence) {
  EXPECT_FALSE(parse("file = \"a.msh\""));
  const auto spec = parse("color_by = { field = \"t\" }");
  ASSERT_TRUE(spec);
  EXPECT_FALSE(spec->step);
  EXPECT_EQ(spec->map, ColorMapKind::Viridis);
  EXPECT_FALSE(spec->range);
}

TEST(ColorByTest, BadValuesPointAtTheKey) {
  EXPECT_NE(parseError("color_by = \"temperature\"")
                .find("scene.toml:1:12: error: mesh[0].color_by must be a table"),
            std::string::npos)
      << parseError("color_by = \"temperature\"");
  EXPECT_NE(parseError("color_by = { map = \"viridis\" }").find("field"), std::string::npos);
  EXPECT_NE(parseError("color_by = { field = \"t\", map = \"virdis\" }").find("viridis"), std::string::npos);
  EXPECT_NE(parseError("color_by = { field = \"t\", range = [1, 1] }").find("min < max"), std::string::npos);
  EXPECT_NE(parseError("color_by = { field = \"t\", range = [1] }").find("two finite numbers"),
            std::string::npos);
  EXPECT_NE(parseError("color_by = { field = \"t\", step = -1 }").find("step"), std::string::npos);
  EXPECT_NE(parseError("color_by = { field = \"t\", colour = 1 }").find("colour"), std::string::npos);
}

TEST(ColorByTest, NodeFieldIsNormalisedOverItsRange) {
  const Mesh mesh = fieldMesh();
  ColorBy spec;
  spec.field = "temperature";
  const FieldColoring coloring = resolveColorBy(spec, mesh);
  EXPECT_EQ(coloring.at, FieldAt::kNode);
  EXPECT_NEAR(coloring.low, 0.0, 1e-6);
  EXPECT_NEAR(coloring.high, 3.0, 1e-6);
  ASSERT_EQ(coloring.t.size(), mesh.positions.size());
  for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3d p = mesh.worldPosition(v);
    EXPECT_NEAR(coloring.t[v], (p.x + 2 * p.y) / 3, 1e-5);
  }
}

TEST(ColorByTest, ExplicitRangeClamps) {
  const Mesh mesh = fieldMesh();
  ColorBy spec;
  spec.field = "temperature";
  spec.range = std::pair{1.0, 2.0};
  const FieldColoring coloring = resolveColorBy(spec, mesh);
  for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3d p = mesh.worldPosition(v);
    EXPECT_NEAR(coloring.t[v], std::clamp(p.x + 2 * p.y - 1, 0.0, 1.0), 1e-5);
  }
}

TEST(ColorByTest, MapsByNameReversedGmshsAndLists) {
  EXPECT_EQ(parse(R"(color_by = { field = "t", map = "RdBu_r" })")->map, *ColorMap::named("RdBu_r"));
  EXPECT_EQ(parse(R"(color_by = { field = "t", map = "grey" })")->map, ColorMapKind::Grey);
  EXPECT_EQ(parse(R"(color_by = { field = "t", map = "gmsh:2" })")->map.name(), "gmsh:2");
  const ColorMap list = parse(R"(color_by = { field = "t", map = ["#000080", "White", [0.5, 0, 0]] })")->map;
  EXPECT_EQ(list.name(), R"(["#000080", "White", [0.5, 0, 0]])");
  ASSERT_EQ(list.colors().size(), 3u);
  EXPECT_EQ(list.colors()[0], (Vec3{0, 0, 128 / 255.0f}));
  EXPECT_EQ(list.colors()[1], (Vec3{1, 1, 1}));
  EXPECT_EQ(list.colors()[2], (Vec3{0.5f, 0, 0}));
  EXPECT_EQ(parse(R"(color_by = { field = "t" })")->scale, ColorScale::Linear);
  EXPECT_EQ(parse(R"(color_by = { field = "t", scale = "log", range = [1e-3, 3] })")->scale, ColorScale::Log);
  // The CLI's spelling: a name, or colours separated by commas.
  EXPECT_EQ(colorMapFromText("turbo", {"--color-map"}), *ColorMap::named("turbo"));
  EXPECT_EQ(colorMapFromText("#000080, white,#800000", {"--color-map"}).colors().size(), 3u);
}

TEST(ColorByTest, LogScaleKeepsValuesForThePixelToPlace) {
  // With a range whose low end is > 0, values below it (0 at the origin) are drawn at the low end:
  // the values are kept as they are and placed on the map after interpolation (FieldMap).
  const Mesh mesh = fieldMesh();
  ColorBy spec;
  spec.field = "temperature";
  spec.scale = ColorScale::Log;
  spec.range = std::pair{0.1, 3.0};
  const FieldColoring coloring = resolveColorBy(spec, mesh);
  EXPECT_EQ(coloring.scale, ColorScale::Log);
  EXPECT_EQ(coloring.low, 0.1);
  EXPECT_EQ(coloring.high, 3.0);
  const MapPosition position(0.1, 3.0, ColorScale::Log);
  for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3d p = mesh.worldPosition(v);
    EXPECT_NEAR(coloring.t[v], p.x + 2 * p.y, 1e-5);
    EXPECT_NEAR(position(coloring.t[v]), std::log(std::max(p.x + 2 * p.y, 0.1) / 0.1) / std::log(30.0), 1e-5);
  }
}

std::string resolveError(const ColorBy& spec, const Mesh& mesh) {
  return test::messageOf([&] { resolveColorBy(spec, mesh); });
}

TEST(ColorByTest, UnknownFieldNamesTheFieldsPresent) {
  const Mesh mesh = fieldMesh();
  ColorBy spec;
  spec.field = "temprature";
  spec.where = {"scene.toml", 7, 12};
  const std::string what = resolveError(spec, mesh);
  EXPECT_EQ(what.rfind("scene.toml:7:12: error: color_by field \"temprature\" is not in ", 0), 0u) << what;
  EXPECT_NE(what.find("(did you mean 'temperature'?); it has \"temperature\" (step 0)"), std::string::npos)
      << what;
  spec.field = "temperature";
  spec.step = 3;
  EXPECT_NE(resolveError(spec, mesh).find("has no step 3"), std::string::npos);
  const Mesh plain = readMsh(std::string(LANCER_TEST_DATA_DIR) + "/msh/square_tri3_v41_ascii.msh");
  EXPECT_NE(resolveError(spec, plain).find("has no fields"), std::string::npos);
}

}  // namespace
}  // namespace lancer
