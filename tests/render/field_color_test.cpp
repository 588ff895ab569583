// color_by through the renderer: a gmsh-made square with the field x + 2 y, seen from above with
// ambient-only white light, shows at each pixel the colour map's colour at (x + 2 y) / 3 (the
// oracle), with linear or sRGB output. The golden image of a lit, tilted one is in
// field_color_golden_test.cpp.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "lancer/image/color_map.hpp"
#include "lancer/image/pixel_encoding.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

const std::string kDataDir = LANCER_TEST_DATA_DIR "/render/";

// Largest channel difference, in 8-bit steps, between the picture and `expected` of the field's value
// x + 2 y (default: viridis at (x + 2 y) / 3), with the mesh's color_by changed by `change`.
double worstError(bool srgb, const std::function<void(ColorBy&)>& change = {},
                  const std::function<Vec3(double)>& expected = {}) {
  SceneDescription description = loadScene(kDataDir + "field_square_top.toml");
  description.render.srgb = srgb;
  if (change) change(*description.meshes[0].colorBy);
  const Scene scene = buildScene(description);
  const Image image = test::renderScene(description, scene);
  const int size = image.width();
  double worst = 0;
  for (int row = 0; row < size; ++row) {
    for (int column = 0; column < size; ++column) {
      const double x = (column + 0.5) / size;
      const double y = 1.0 - (row + 0.5) / size;
      const Vec3 colour = expected
                              ? expected(x + 2 * y)
                              : colorMapLookup(ColorMapKind::Viridis, static_cast<float>((x + 2 * y) / 3));
      const Rgba& pixel = image.at(column, row);
      const float got[3] = {pixel.r, pixel.g, pixel.b};
      const float want[3] = {colour.x, colour.y, colour.z};
      for (int c = 0; c < 3; ++c) {
        const float shown = srgb ? srgbFromLinear(got[c]) : got[c];
        worst = std::max(worst, std::abs(shown - want[c]) * 255.0);
      }
    }
  }
  return worst;
}

TEST(FieldColor, LinearOutputShowsTheMapColours) { EXPECT_LT(worstError(false), 2.0); }

TEST(FieldColor, SrgbOutputShowsTheSameMapColours) { EXPECT_LT(worstError(true), 2.0); }

TEST(FieldColor, AnyNamedMapOrListShowsItsColours) {
  const ColorMap rdbu = *ColorMap::named("RdBu_r");
  EXPECT_LT(worstError(
                false, [&](ColorBy& c) { c.map = rdbu; },
                [&](double v) { return rdbu(static_cast<float>(v / 3)); }),
            2.0);
  const ColorMap list = ColorMap::fromColors({{0, 0, 0.5f}, {1, 1, 1}, {0.5f, 0, 0}}, "list");
  EXPECT_LT(
      worstError(
          true, [&](ColorBy& c) { c.map = list; }, [&](double v) { return list(static_cast<float>(v / 3)); }),
      2.0);
}

TEST(FieldColor, LogScaleShowsTheInterpolatedValuesPlace) {
  // x + 2 y is linear, so the value interpolated over each face is exact and the pixel shows its
  // place on the log scale over [0.1, 3]; values below 0.1 (down to 0) at the map's low end.
  const ColorMap turbo = *ColorMap::named("turbo");
  const MapPosition position(0.1, 3, ColorScale::Log);
  const auto logScale = [](ColorBy& c) {
    c.map = *ColorMap::named("turbo");
    c.scale = ColorScale::Log;
    c.range = std::pair{0.1, 3.0};
  };
  EXPECT_LT(worstError(false, logScale, [&](double v) { return turbo(position(v)); }), 2.0);
}

TEST(FieldColor, UncolouredMeshesCostNothing) {
  SceneDescription description = loadScene(kDataDir + "field_square_top.toml");
  description.meshes[0].colorBy.reset();
  const Scene scene = buildScene(description);
  EXPECT_FALSE(scene.fieldColors);  // no per-face or per-vertex arrays at all
}

TEST(FieldColor, UnknownFieldIsAnErrorAtTheSceneKey) {
  SceneDescription description = loadScene(kDataDir + "field_square_top.toml");
  description.meshes[0].colorBy->field = "pressure";
  try {
    buildScene(description);
    FAIL() << "no error";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("field_square_top.toml:21:12: error: color_by field \"pressure\" is not in"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("it has \"temperature\" (step 0)"), std::string::npos) << what;
  }
}

TEST(FieldColor, ElementDataIsConstantPerFace) {
  // The same square with x + 2 y as $ElementData (gmsh evaluates it at each element's last node).
  SceneDescription description = loadScene(kDataDir + "field_square_top.toml");
  description.meshes[0].file = LANCER_TEST_DATA_DIR "/fields/element_xy_v41_bin.msh";
  const Scene scene = buildScene(description);
  ASSERT_TRUE(scene.fieldColors);
  const FieldColors& fields = *scene.fieldColors;
  ASSERT_EQ(fields.faceFieldT.size(), scene.geometry.faces.size());
  EXPECT_TRUE(fields.vertexFieldT.empty());
  for (std::size_t f = 0; f < scene.geometry.faces.size(); ++f) {
    EXPECT_EQ(fields.faceColorMap[f], (1 + static_cast<int>(ColorMapKind::Viridis)) | FieldColors::kPerFace);
    const Vec3d p =
        scene.geometry.origin + toDouble(scene.geometry.positions[scene.geometry.faces[f].vertex[2]]);
    const double low = fields.legends.at(0).low, high = fields.legends.at(0).high;  // the triangles' range
    EXPECT_NEAR(fields.faceFieldT[f], (p.x + 2 * p.y - low) / (high - low), 1e-5) << f;
  }
}

}  // namespace
}  // namespace lancer
